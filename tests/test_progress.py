"""Progress of long runs: the API's ``progress(done, total)`` callback and the command
line's bar (drawn on stderr only when stderr is a terminal)."""
import io
from pathlib import Path

import pytest

from trussfe import api
from trussfe.cli import main
from trussfe.cli import progress as cli_progress

MESHES = Path(__file__).resolve().parents[1] / "meshes"

RUNS = [
    ("simulate", "triangular_truss_motion_active.toml",
     {"motion": "triangular_truss_motion_3s.toml"}),
    ("elastic", "triangular_truss_motion_active.toml",
     {"motion": "triangular_truss_motion_3s.toml"}),
    ("transient", "triangular_truss_motion_active.toml",
     {"motion": "triangular_truss_motion_3s.toml", "dt": 0.1}),
    ("trace", "mech_fourbar.toml", {"drive": "2:y", "step": 0.05, "steps": 5}),
    ("postcritical", "postcritical_von_mises.toml", {"steps": 20}),
    ("modes", "triangular_truss_static.toml", {"bar_model": "pinned-beam"}),
]


@pytest.mark.parametrize("name, model, options", RUNS, ids=[r[0] for r in RUNS])
def test_progress_callback_counts_up_to_its_total(name, model, options):
    calls = []
    result = getattr(api, name)(MESHES / model, progress=lambda d, t: calls.append((d, t)),
                                **options)
    assert calls, "no progress reported"
    for done, total in calls:
        assert isinstance(done, int) and isinstance(total, int) and 0 <= done <= total
    # within one phase (one total) the count never goes back
    for (d0, t0), (d1, t1) in zip(calls, calls[1:]):
        if t0 == t1:
            assert d1 >= d0
    # the same results as without a callback
    again = getattr(api, name)(MESHES / model, **options)
    assert again.to_dict() == result.to_dict()


def test_a_progress_callback_may_stop_the_run():
    """The callback may raise (Ctrl-C on a terminal): the run stops there."""
    def stop(done, total):
        if done >= 2:
            raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        api.postcritical(MESHES / "postcritical_von_mises.toml", steps=20, progress=stop)


def test_bar_only_on_a_terminal(monkeypatch):
    class Tty(io.StringIO):
        def isatty(self):
            return True

        def fileno(self):
            raise OSError("no descriptor")
    monkeypatch.setattr("sys.stderr", io.StringIO())
    with cli_progress.progress_bar("x") as tick:
        assert tick is None
    fake = Tty()
    monkeypatch.setattr("sys.stderr", fake)
    with cli_progress.progress_bar("postcritical") as tick:
        tick(0, 4)
        tick(4, 4)
        tick(1, 10)          # a second phase with its own total
    assert "postcritical" in fake.getvalue()


def test_command_output_has_no_bar_off_a_terminal(tmp_path, capsys):
    assert main(["postcritical", str(MESHES / "postcritical_von_mises.toml"), "--steps", "20",
                 "--json", str(tmp_path / "p.json")]) == 0
    assert capsys.readouterr().err == ""

