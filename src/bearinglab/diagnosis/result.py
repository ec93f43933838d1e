"""The result of a diagnosis: :class:`Diagnosis` (to_dict, to_pandas, plot)."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

from ..kinematics import DefectFrequencies
from ..signal import EnvelopeSpectrum
from .families import FREQUENCY
from .verdict import NO_FAULT, significance


@dataclass(frozen=True)
class Diagnosis:
    """What envelope analysis finds in a vibration record.

    Attributes
    ----------
    verdict : str
        ``"no fault detected"``, a fault (``"outer_race"``, ``"inner_race"``, ``"ball"``,
        ``"cage"``) or ``"compound: a + b"``.
    faults : tuple of str
        The faults found, most significant first.
    families : dict
        Per family: ``p_value`` (upper bound of the chance that noise alone shows the
        series), ``significance`` (-log10 p), ``passed``, the ``method`` that showed it
        best, the fitted ``fundamental_hz`` and ``slip`` and its ``lines``.
    false_alarm : float
        Probability of a false alarm on a record with no fault, at most [-].
    alpha : float
        Level of each family test: ``false_alarm`` / (families x methods) [-].
    spectrum : EnvelopeSpectrum
        Squared envelope spectrum of the method that showed the primary fault (else the
        first method): ``frequency`` [Hz], ``amplitude`` [unit of the samples squared;
        for ``ies`` sqrt(2 x the improved envelope spectrum over its noise level), no
        unit], ``band`` [Hz] or None (for ``ies`` the spectral frequencies averaged).
    spectra : dict
        Method -> its MethodSpectrum (with the normalised power ``z``).
    peaks : tuple of dict
        The most significant envelope lines, labelled: ``frequency_hz``, ``amplitude``,
        ``z``, ``significance``, ``matched`` (``bpfo``, ``bpfi``, ``ball_defect``, ``ftf``,
        ``shaft``, ``supply``, ``mesh`` or None), ``harmonic``, ``deviation`` and for
        sidebands ``sideband_of``, ``sideband_harmonic``, ``sideband_order``,
        ``modulation``.
    frequencies : DefectFrequencies
        Kinematic frequencies at the speed used.
    speed : dict
        ``given_rpm``, ``used_rpm``, ``source`` ("given" or "signal") and the search.
    sample_rate, channel, max_frequency, resolution, methods, tolerances, warnings
        As their names say (Hz, fractions).
    record : tuple or None
        (samples, sample rate [Hz], radial load [N] or None): what the sizing of a race
        defect reads (:attr:`defect_sizes`).
    second_look : dict or None
        When faults were read after the first fault's impacts were removed
        (:mod:`.residual`): ``removed`` (that fault), ``rate_hz`` (the rate its impacts
        were removed at) and ``added`` (the faults read then); else None.
    """

    verdict: str
    faults: tuple
    families: dict
    false_alarm: float
    alpha: float
    spectrum: EnvelopeSpectrum
    spectra: dict = field(repr=False)
    peaks: tuple
    frequencies: DefectFrequencies
    speed: dict
    sample_rate: float
    channel: str | None
    max_frequency: float
    methods: tuple
    tolerances: dict
    harmonics: int
    warnings: tuple
    reason: str
    modulation: tuple = ()
    record: tuple | None = field(default=None, repr=False, compare=False)
    second_look: dict | None = None

    # ---------------------------------------------------------- verdict views
    @property
    def likely_fault(self) -> str | None:
        """The verdict, or None when no fault was detected."""
        return None if self.verdict == NO_FAULT else self.verdict

    @property
    def primary_fault(self) -> str | None:
        """The most significant fault, or None."""
        return self.faults[0] if self.faults else None

    @property
    def scores(self) -> dict:
        """Family -> significance -log10 p [-]."""
        return {name: f["significance"] for name, f in self.families.items()}

    @property
    def threshold(self) -> float:
        """Significance a family must exceed: -log10 ``alpha`` [-]."""
        return significance(self.alpha)

    @property
    def band(self):
        """Demodulation band of the spectrum shown (None: whole band) [Hz]."""
        return self.spectrum.band

    @property
    def kurtogram(self):
        """The fast kurtogram of the ``drs-sk`` method, when it ran (else None)."""
        spec = self.spectra.get("drs-sk")
        return None if spec is None else spec.kurtogram

    @property
    def resolution(self) -> float:
        """Bin spacing of the envelope spectra [Hz]."""
        return float(self.spectrum.frequency[1] - self.spectrum.frequency[0])

    @property
    def ball_defect_frequency_hz(self) -> float | None:
        """Ball-defect frequency fitted to the ball series when a ball fault was found
        [Hz], else None."""
        if "ball" not in self.faults:
            return None
        return self.families["ball"]["fundamental_hz"]

    @cached_property
    def defect_sizes(self) -> tuple:
        """The width of each race defect found, in the order of :attr:`faults`: a
        :class:`.sizing.DefectSize` per race fault (:func:`.sizing.size_defect`, read
        from the record when first asked for); empty without a race fault."""
        from .sizing import RACES, size_defect

        if self.record is None:
            return ()
        x, fs, load = self.record
        bearing = self.frequencies.bearing
        return tuple(
            size_defect(x, fs, bearing, f, self.families[f]["fundamental_hz"], radial_load=load)
            for f in self.faults
            if f in RACES
        )

    @property
    def defect_size(self):
        """The :class:`.sizing.DefectSize` of the verdict's first race fault, or None."""
        return self.defect_sizes[0] if self.defect_sizes else None

    # ---------------------------------------------------------- exports
    def to_dict(self) -> dict:
        """JSON-ready dict in engineering units (Hz, rpm; amplitudes in the squared
        envelope's unit); ``defect_size`` (the verdict's first race fault's width, null
        without one) and ``defect_sizes`` (every race fault's). For a roller bearing the
        rolling element's family is named "roller" (the verdict too)."""
        bearing = getattr(self.frequencies, "bearing", None)
        if getattr(bearing, "rolling_element", "ball") == "roller":
            return _as_rollers(self._dict())
        return self._dict()

    def _dict(self) -> dict:
        return {
            "verdict": self.verdict,
            "likely_fault": self.likely_fault,
            "primary_fault": self.primary_fault,
            "faults": list(self.faults),
            "false_alarm_probability": self.false_alarm,
            "test_level": self.alpha,
            "threshold_significance": self.threshold,
            "families": {k: dict(v) for k, v in self.families.items()},
            "scores": self.scores,
            "reason": self.reason,
            "cage_modulation_of": list(self.modulation),
            "second_look": None
            if self.second_look is None
            else {
                "removed": self.second_look["removed"],
                "rate_hz": float(self.second_look["rate_hz"]),
                "added": list(self.second_look["added"]),
            },
            "channel": self.channel,
            "sample_rate_hz": self.sample_rate,
            "methods": list(self.methods),
            "method_shown": next(iter(self.spectra))
            if not self.faults
            else self.families[self.faults[0]]["method"],
            "band_hz": None if self.band is None else [float(b) for b in self.band],
            "bands_hz": {
                m: None if s.band is None else [float(b) for b in s.band]
                for m, s in self.spectra.items()
            },
            "band_kurtosis": None if self.kurtogram is None else self.kurtogram.kurtosis,
            "resolution_hz": self.resolution,
            "max_frequency_hz": self.max_frequency,
            "harmonics": self.harmonics,
            "tolerances": {k: {"below": v[0], "above": v[1]} for k, v in self.tolerances.items()},
            "speed": dict(self.speed),
            "kinematic": self.frequencies.to_dict(),
            "peaks": [dict(p) for p in self.peaks],
            "ball_defect_frequency_hz": self.ball_defect_frequency_hz,
            "defect_size": None if self.defect_size is None else self.defect_size.to_dict(),
            "defect_sizes": [s.to_dict() for s in self.defect_sizes],
            "warnings": list(self.warnings),
        }

    def to_pandas(self):
        """Table of the labelled envelope lines (one row per peak, most significant first)."""
        import pandas as pd

        from ..signal.lines import LINE_KEYS

        # a labelled line's keys, with the diagnosis' normalised power and significance
        columns = [*LINE_KEYS[:2], "z", "significance", *LINE_KEYS[2:]]
        return pd.DataFrame([{c: p.get(c) for c in columns} for p in self.peaks], columns=columns)

    def families_table(self):
        """Table of the family tests: family, method, significance, threshold, passed,
        fundamental_hz, slip, lines."""
        import pandas as pd

        rows = [
            {
                "family": k,
                "method": v["method"],
                "significance": v["significance"],
                "threshold": self.threshold,
                "passed": v["passed"],
                "fundamental_hz": v["fundamental_hz"],
                "slip": v["slip"],
                "lines": len(v["lines"]),
            }
            for k, v in self.families.items()
        ]
        return pd.DataFrame(rows)

    def plot(self, path=None, ax=None):
        """Squared envelope spectrum with the kinematic lines and the lines found; on a new
        figure, below it, the event-aligned average of each race defect's passages with
        its entry and exit marked (:meth:`.sizing.DefectSize.plot`).

        Parameters
        ----------
        path : str or Path, optional
            Also save the figure there (.png, .svg or .pdf; atomically; the figure is
            closed).
        ax : matplotlib Axes, optional
            Where to draw the spectrum alone; a new figure otherwise.

        Returns
        -------
        (figure, axes)
            The spectrum's axes (the averages' are ``figure.axes[1:]``).
        """
        from ..plotting import _pyplot, draw_spectrum, save_figure

        plt = _pyplot()
        sizes = []
        if ax is None:
            sizes = [s for s in self.defect_sizes if s.lag.size]
            fig = plt.figure(figsize=(11, 4.5 + 5.0 * len(sizes)))
            grid = fig.add_gridspec(
                1 + 2 * len(sizes), 1, height_ratios=[4.5] + [2.5] * 2 * len(sizes)
            )
            ax = fig.add_subplot(grid[0])
        else:
            fig = ax.figure
        method = self.to_dict()["method_shown"]
        band = (
            "whole band" if self.band is None else f"band {self.band[0]:.0f}-{self.band[1]:.0f} Hz"
        )
        draw_spectrum(
            ax,
            self.spectrum,
            self.peaks,
            self.frequencies,
            self.max_frequency,
            title=f"{self.frequencies.bearing.name or 'bearing'} at "
            f"{self.frequencies.shaft_hz * 60:.6g} rpm, channel "
            f"{self.channel or '-'}, {method}, {band}: {self.verdict}",
            ylabel="squared envelope amplitude",
            harmonics=self.harmonics,
            trace="squared envelope spectrum",
            # shaft harmonics are not a bearing fault: only fault lines and sidebands in colour
            highlight=lambda p: p.get("matched") in FREQUENCY.values() or p.get("sideband_of"),
        )
        for i, size in enumerate(sizes):
            top = fig.add_subplot(grid[1 + 2 * i])
            size.plot(ax=(top, fig.add_subplot(grid[2 + 2 * i], sharex=top)))
        fig.tight_layout()
        if path is not None:
            try:
                save_figure(fig, path)  # closes the figure
            except Exception:
                plt.close(fig)
                raise
        return fig, ax


def measured_ball_defect_frequency(matched_peaks) -> float | None:
    """Ball-defect frequency read off labelled envelope lines, ``matched_peaks`` (the
    dicts of :func:`bearinglab.signal.match_peaks`) [Hz].

    The strongest line matched to ``ball_defect`` at harmonic 1; if there is none, half
    the strongest matched at harmonic 2; else None. Sidebands are not used.

    Parameters
    ----------
    matched_peaks : iterable of dict
        Labelled lines (:func:`bearinglab.signal.match_peaks`), each with ``frequency_hz``
        [Hz], ``amplitude``, ``matched`` and ``harmonic``.

    Examples
    --------
    >>> measured_ball_defect_frequency([
    ...     {"frequency_hz": 270.0, "amplitude": 1.0, "matched": "ball_defect", "harmonic": 2}])
    135.0
    """
    for n in (1, 2):
        lines = [
            p for p in matched_peaks if p.get("matched") == "ball_defect" and p.get("harmonic") == n
        ]
        if lines:
            return float(max(lines, key=lambda p: p["amplitude"])["frequency_hz"]) / n
    return None


def _as_rollers(d: dict) -> dict:
    """A diagnosis' dict with the rolling element's family named "roller": the verdict,
    the faults, the families, scores and tolerances, the peaks' matches and the frequency
    of its defect."""

    def name(text):
        return {"ball": "roller", "ball_defect": "roller_defect"}.get(text, text)

    d = dict(d)
    for key in ("likely_fault", "primary_fault"):
        d[key] = name(d[key])
    d["verdict"] = " ".join("roller" if w == "ball" else w for w in str(d["verdict"]).split(" "))
    d["faults"] = [name(f) for f in d["faults"]]
    d["cage_modulation_of"] = [name(f) for f in d["cage_modulation_of"]]
    if d.get("second_look"):
        look = d["second_look"]
        added = [name(f) for f in look["added"]]
        d["second_look"] = {**look, "removed": name(look["removed"]), "added": added}
    for key in ("families", "scores", "tolerances"):
        if isinstance(d.get(key), dict):
            d[key] = {name(k): v for k, v in d[key].items()}
    if isinstance(d.get("peaks"), list):
        d["peaks"] = [
            {k: name(v) if k in ("matched", "sideband_of") else v for k, v in p.items()}
            for p in d["peaks"]
        ]
    d["roller_defect_frequency_hz"] = d.pop("ball_defect_frequency_hz")
    return d
