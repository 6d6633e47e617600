"""The load–displacement plot of a post-critical path (trussfe.nonlinear.plot)."""
from pathlib import Path

from trussfe import api

MESHES = Path(__file__).resolve().parents[1] / "meshes"


def test_path_plot_gives_the_equilibrium_path_its_own_panel(tmp_path):
    """The dome's mechanism motion is ~60× wider than its equilibrium path: the plot draws
    the equilibrium path on its own scale beside the whole path (two panels), where a path
    without such a motion keeps one panel."""
    from matplotlib.image import imread
    from trussfe.nonlinear.plot import write_plot
    dome = api.postcritical(MESHES / "postcritical_dome.toml").solution
    vm = api.postcritical(MESHES / "postcritical_von_mises.toml", steps=40).solution
    write_plot(tmp_path / "dome.png", dome)
    write_plot(tmp_path / "vm.png", vm)
    wide, single = imread(tmp_path / "dome.png"), imread(tmp_path / "vm.png")
    assert wide.shape[1] > 1.6 * single.shape[1]
