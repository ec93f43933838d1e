"""One output of a study against two of its inputs."""

from __future__ import annotations

from ..errors import InputError

#: A pivot of at most this many x or y values is drawn as a map; more (random inputs)
#: as a scatter coloured by the output.
MAX_MAP_VALUES = 200


def _label(name: str) -> str:
    """``radial_load_n`` -> "radial load [N]" (unit suffixes of docs/conventions.md)."""
    units = {
        "_n_per_um": "N/um",
        "_n_per_m": "N/m",
        "_mm2_s": "mm^2/s",
        "_m_s2": "m/s^2",
        "_nmm": "N mm",
        "_rpm": "rpm",
        "_mm": "mm",
        "_um": "um",
        "_deg": "deg",
        "_mrad": "mrad",
        "_hz": "Hz",
        "_khz": "kHz",
        "_db": "dB",
        "_pa": "Pa",
        "_kg": "kg",
        "_w": "W",
        "_s": "s",
        "_hours": "h",
        "_n": "N",
    }
    for suffix, unit in units.items():
        if name.endswith(suffix):
            return f"{name[: -len(suffix)].replace('_', ' ')} [{unit}]"
    return name.replace("_", " ")


def plot_study(table, output: str, x: str, y: str, *, path=None, ax=None):
    """Map of ``output`` over inputs ``x`` and ``y``.

    Cases that share (x, y) but differ in other inputs are averaged (the title says so);
    failed cases are left out. Random (scattered) inputs are drawn as points coloured by
    the output.

    Parameters
    ----------
    table : pandas.DataFrame
        A study table (:func:`bearinglab.study.read_study`).
    output, x, y : str
        Column names.
    path : str or Path, optional
        Also save the figure (.png, .svg, .pdf; the figure is then closed).
    ax : matplotlib Axes, optional

    Returns
    -------
    (figure, axes)
    """
    from ..plotting import figure_axes, save_figure

    for what, name in (("output", output), ("x", x), ("y", y)):
        if name not in table.columns:
            raise InputError(what, name, "a column of the study: " + ", ".join(table.columns))
    ok = table[table["error"].isna()] if "error" in table.columns else table
    if ok.empty:
        raise InputError("output", output, "a study with at least one case that did not fail")
    fig, ax = figure_axes(ax, figsize=(7, 5))
    others = [
        c
        for c in ok.columns
        if c not in (x, y, output, "case", "error")
        and c in table.attrs.get("inputs", ok.columns)
        and ok[c].nunique() > 1
    ]
    nx, ny = ok[x].nunique(), ok[y].nunique()
    if nx <= MAX_MAP_VALUES and ny <= MAX_MAP_VALUES and nx * ny <= 4 * len(ok):
        grid = ok.pivot_table(index=y, columns=x, values=output, aggfunc="mean")
        mesh = ax.pcolormesh(
            grid.columns.to_numpy(float),
            grid.index.to_numpy(float),
            grid.to_numpy(float),
            shading="nearest",
            cmap="viridis",
        )
    else:
        mesh = ax.scatter(ok[x], ok[y], c=ok[output], s=12, cmap="viridis")
    fig.colorbar(mesh, ax=ax, label=_label(output))
    ax.set_xlabel(_label(x))
    ax.set_ylabel(_label(y))
    mean = ok.groupby([x, y]).size().max() > 1
    ax.set_title(_label(output) + (" (mean over other inputs)" if mean and others else ""))
    if path is not None:
        save_figure(fig, path)
    return fig, ax
