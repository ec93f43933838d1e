"""The trend's remaining useful life (issue 29) and what it learns from runs to failure:
the challenge's accuracy, the predictive law against SciPy's, the estimate's two bases, a
short series, learning from a user's own folder of runs, and the outputs (JSON, table,
page)."""

import math

import numpy as np
import pytest
from conftest import run_json, write_pronostia

from bearinglab.errors import InputError
from bearinglab.trend import LearnedRuns, learn_runs, trend_records
from bearinglab.trend.learning import packaged_learned, read_learned
from bearinglab.trend.life import Predictive, best_estimate, phm2012_accuracy

LIFE_KEYS = {"estimate_s", "low_s", "high_s", "at_time_s", "learned_from", "method", "basis"}


def noise(records: int, seed: int = 0, n: int = 1024, scale: float = 0.3) -> np.ndarray:
    return scale * np.random.default_rng(seed).standard_normal((records, 2, n))


def failing_run(records: int, seed: int, wander: float = 0.0, n: int = 1024) -> np.ndarray:
    """Noise whose last fifth grows tenfold (a run to failure, 10 s per record), its level
    wandering by ``wander`` (log units per record, a random walk) before."""
    x = noise(records, seed, n=n)
    if wander:
        walk = np.cumsum(np.random.default_rng(seed + 99).normal(0, wander, records))
        x *= np.exp(walk - walk[0])[:, None, None]
    onset = int(0.8 * records)
    x[onset:] *= np.geomspace(1.0, 10.0, records - onset)[:, None, None]
    return x


# ------------------------------------------------------------------ the arithmetic
def test_the_challenge_accuracy_halves_every_5_percent_late_and_20_percent_early():
    # Nectoux et al. (PHM 2012 challenge): Er = 100 (actual - estimate) / actual
    a = phm2012_accuracy(1000.0, [1000.0, 950.0, 800.0, 1050.0, 1100.0])
    np.testing.assert_allclose(a, [1.0, 0.5**0.25, 0.5, 0.5, 0.25])


@pytest.mark.parametrize("elapsed", [0.0, 50.0, 400.0])
def test_the_predictive_law_is_a_truncated_student_t_of_the_logs(elapsed):
    from scipy import stats

    times = [100.0, 150.0, 300.0, 500.0, 90.0]
    p = Predictive.of(times)
    logs = np.log(times)
    t = stats.t(4, loc=logs.mean(), scale=logs.std(ddof=1) * math.sqrt(1 + 1 / 5))
    q = np.array([0.1, 0.5, 0.9])
    survive = t.sf(np.log(elapsed)) if elapsed > 0 else 1.0
    expected = np.exp(t.isf(survive * (1 - q))) - elapsed
    np.testing.assert_allclose(p.quantiles(elapsed, q), expected, rtol=1e-3)


def test_a_wide_law_gives_an_early_estimate():
    # late estimates cost four times more per per cent: the best one is below the median
    samples = np.geomspace(100.0, 10000.0, 201)
    assert best_estimate(samples) < np.median(samples)
    assert best_estimate(np.full(10, 500.0)) == pytest.approx(500.0)


# ------------------------------------------------------------------ on series
def test_a_healthy_series_gets_a_remaining_life_from_survival(tmp_path):
    r = trend_records(
        write_pronostia(tmp_path, noise(90, seed=1)),
        settle_records=5,
        baseline_records=30,
        persistence=30.0,
    )
    d = r.to_dict()["remaining_life"]
    assert set(d) == LIFE_KEYS and d["basis"] == "survival"
    assert d["at_time_s"] == pytest.approx(r.times[-1])
    assert 0 < d["low_s"] <= d["estimate_s"] <= d["high_s"]
    assert "PHM 2012" in d["learned_from"] and "lives" in d["method"]
    # the same bearing, older: less life left
    younger = r.remaining_life.history[1][0]
    assert d["estimate_s"] < younger


def test_a_short_series_still_gets_a_trend_and_an_estimate(tmp_path):
    # the challenge's shortest test run holds 172 snapshots (28 min): shorter than the
    # default settling and baseline (600 + 1200 s at 10 s per snapshot)
    r = trend_records(write_pronostia(tmp_path, noise(172, seed=2)))
    assert any("shortened" in w for w in r.warnings)
    assert r.remaining_life is not None and r.remaining_life.estimate > 0


def test_after_the_alarm_the_estimate_rests_on_the_degradation_seen(tmp_path):
    r = trend_records(
        write_pronostia(tmp_path, failing_run(120, seed=3)),
        persistence=30.0,
        settle_records=5,
        baseline_records=30,
    )
    assert r.alarm is not None
    life = r.remaining_life
    assert life.basis == "degradation"
    # an estimate at every history point: survival before the alarm, degradation after
    times, estimates, lows, highs = life.history
    assert all(lo <= e <= hi for e, lo, hi in zip(estimates, lows, highs, strict=True))


# ------------------------------------------------------------------ learning
@pytest.fixture(scope="module")
def runs_folder(tmp_path_factory):
    """Three runs to failure of different lives (300, 360, 420 records of 512 samples, 10 s
    apart) whose level wanders as a real machine's does."""
    root = tmp_path_factory.mktemp("runs")
    for i, n in enumerate((300, 360, 420)):
        write_pronostia(root / f"run{i}", failing_run(n, seed=10 + i, wander=0.03, n=512))
    return root


def test_a_user_learns_from_a_folder_of_runs_to_failure(capsys, runs_folder, tmp_path):
    # (short runs: a short baseline, so that their first halves hold healthy monitoring)
    learned = learn_runs(runs_folder, settle=None, settle_n=5, baseline=None, baseline_n=30)
    assert isinstance(learned, LearnedRuns)
    assert [row["run"] for row in learned.runs] == ["run0", "run1", "run2"]
    assert [row["life_s"] for row in learned.runs] == pytest.approx([2990.0, 3590.0, 4190.0])
    assert learned.calibration.excursions >= 5 and learned.life["lives"]["n"] == 3
    assert "healthy first halves of 3 runs" in learned.calibration.source
    path = learned.write(tmp_path / "learned.json")
    again = read_learned(path)
    assert again.to_dict() == learned.to_dict()
    r = trend_records(runs_folder / "run1", learn_from=path, persistence=30.0)
    assert r.learned.source == learned.source
    assert "run" in r.to_dict()["remaining_life"]["learned_from"]
    # a folder of runs is learned from on the fly, as the command line takes it (with the
    # default settings these runs are too short to learn limits from: the lives are learned)
    d = run_json(capsys, "trend", str(runs_folder / "run2"), "--learn-from", str(runs_folder))
    assert "too few to learn limits from" in d["rule"]["calibration"]["source"]
    assert runs_folder.name in d["remaining_life"]["learned_from"]


def test_runs_too_quiet_to_learn_limits_from_keep_the_packaged_limits(tmp_path):
    for i, n in enumerate((200, 250)):
        write_pronostia(tmp_path / f"run{i}", noise(n, seed=20 + i))
    learned = learn_runs(tmp_path)
    assert "too few to learn limits from" in learned.calibration.source
    assert learned.calibration.excursions == packaged_learned().calibration.excursions
    assert learned.life["lives"]["n"] == 2


@pytest.mark.parametrize("what", ["nothing", "one run", "not json"])
def test_what_cannot_be_learned_from_is_an_input_error(tmp_path, runs_folder, what):
    source = tmp_path / "source"
    if what == "one run":
        write_pronostia(source / "run0", failing_run(60, seed=1))
    elif what == "quiet":
        for i in range(2):
            write_pronostia(source / f"run{i}", noise(60, seed=i))
    elif what == "not json":
        source = tmp_path / "learned.json"
        source.write_text("{ not json")
    with pytest.raises(InputError) as info:
        trend_records(runs_folder / "run0", learn_from=source)
    assert info.value.parameter == "learn_from"


def test_the_packaged_defaults_name_the_six_learning_runs():
    learned = packaged_learned()
    assert len(learned.runs) == 6 and learned.life["lives"]["n"] == 6
    assert "every 10th snapshot" in learned.source
    assert learned.measured["hours"] > 0 and learned.measured["firings"] == 0


# ------------------------------------------------------------------ outputs
def test_table_and_page_show_the_rates_the_zones_and_the_remaining_life(capsys, tmp_path):
    from bearinglab.cli import main
    from bearinglab.report.trend import write_trend_page

    folder = write_pronostia(tmp_path / "run", failing_run(120, seed=4))
    args = ["--settle-records", "5", "--baseline-records", "30", "--persistence-s", "30"]
    assert main(["trend", str(folder), *args]) == 0
    out = capsys.readouterr().out
    for words in ("false alarms measured", "remaining life", "learning runs"):
        assert words in " ".join(out.split()), words
    r = trend_records(
        folder,
        settle_records=5,
        baseline_records=30,
        persistence=30.0,
        unit="g",
        machine="group2-rigid",
    )
    page = write_trend_page(r, tmp_path / "t.html").read_text()
    assert "False alarms measured" in page and "false alarms stated" in page
    assert "ISO 20816 zones of group2-rigid" in page and "10-1000 Hz" in page
    assert "misses most of the energy" in page
    assert "Remaining useful life" in page and page.count("data:image/png;base64") == 2
