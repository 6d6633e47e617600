# SPDX-License-Identifier: MIT
"""A picture of a model: members, ids, supports, loads and, from a results file, member
forces, utilisation and the deformed shape (``trussfe show``, docs/cli.md).

What is drawn
-------------
* Members as lines, coloured by their section (one colour per section name, with a legend)
  or by a per-member result from a results document (:func:`read_results`): the axial force
  (tension positive, a diverging map centred on zero) or the utilisation (:func:`utilisation`,
  0 to at least 1).
* Node ids at the nodes and member ids at the member midpoints (models of up to
  :data:`LABEL_LIMIT` nodes plus members; larger models would drown in text).
* Supports as symbols at their nodes: a filled triangle where every translation is fixed
  (a pin), a hollow triangle where some are (a roller), a filled square where the rotations
  are fixed as well (a clamp), a hollow diamond (a wire sphere in 3-D views) where a node
  has an elastic support (``springs``).
* Nodal forces as arrows pointing the way the force acts, the largest drawn at
  :data:`LOAD_ARROW` of the model size and the others in proportion, each labelled with its
  magnitude in N (a nodal moment adds ``M = ... N·m`` to the label); loads along members
  (``member_loads``) as arrows where they act, labelled with their force or intensity.
* With displacements in the results, the undeformed model in light grey and the deformed
  shape in colour, magnified so that the largest translation is :data:`DEFORMED_SIZE` of the
  model size unless a scale is given; the magnification is in the title.

pyvista renders off-screen where OpenGL works, matplotlib (Agg, no pyplot) everywhere else
(:func:`trussfe.io.render_backend.plot_backend`).  2-D models are seen along z, 3-D models from
an isometric direction.  The PNG is written atomically (:func:`trussfe.io.output.atomic_path`).
"""
from __future__ import annotations

import json
import logging
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..mechanics.euler import member_euler_loads
from ..mechanics.geometry import local_axes
from .regular_file import read_regular_file
from ..model.structure import Structure
from .output import atomic_path
from .render_backend import plot_backend

log = logging.getLogger(__name__)

__all__ = ["COLOR_BY", "PictureResults", "draw_model", "read_results", "results_from_document",
           "utilisation"]

#: What members can be coloured by.
COLOR_BY = ("section", "axial_force", "utilisation")
#: Largest number of nodes plus members whose ids are written on the picture.
LABEL_LIMIT = 80
#: Length of the largest load arrow, as a fraction of the model size.
LOAD_ARROW = 0.18
#: Size of the largest drawn displacement, as a fraction of the model size.
DEFORMED_SIZE = 0.1
#: Default picture size, pixels.
DEFAULT_SIZE = (1000, 800)
#: Fewest and most pixels a picture may have per side (``show --size``, ``trussfe.show``).
PIXELS_PER_SIDE = (200, 8000)


@dataclass(frozen=True)
class PictureResults:
    """Results of one analysis, arranged as the model's nodes and members.

    Attributes
    ----------
    source : str
        File the results were read from.
    command : str
        The command that wrote them (``"static"``, ``"buckling"``, ...).
    axial_force : ndarray, shape (m,)
        Member axial force, N, tension positive.
    max_von_mises : ndarray, shape (m,) or None
        Largest von Mises stress of each member, Pa.
    displacement : ndarray, shape (n, dim) or None
        Nodal translations, m.
    case : str or None
        The load case or combination drawn, when the results hold several.
    compression : ndarray, shape (m,) or None
        Largest compression along each member, N (0 where none): over its midpoint force,
        its end forces and its ``stations`` (point loads and self-weight make the axial
        force vary along a member); None: the midpoint compression.
    """

    source: str
    command: str
    axial_force: np.ndarray
    max_von_mises: np.ndarray | None
    displacement: np.ndarray | None
    case: str | None = None
    compression: np.ndarray | None = None


def _number(value, where: str, item: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise InputError(where, f"{item} must be a finite number, got {value!r:.40}")
    return float(value)


def read_results(path: str | Path, structure: Structure, case: str | None = None
                 ) -> PictureResults:
    """Read a results document (``trussfe static --json``, or any document with per-member
    ``axial_force``) and arrange it as ``structure``'s nodes and members.

    Parameters
    ----------
    path : str or Path
        The JSON file.
    structure : Structure
        The model the results belong to: every member must be in the document, and node
        displacements, where given, for every node.
    case : str, optional
        The load case or combination to draw from a document of several
        (``trussfe static --all``); required there.

    Returns
    -------
    PictureResults

    Raises
    ------
    InputError
        The file cannot be read, is not JSON, or does not match the model (named item).
    """
    where = str(path)
    if Path(path).is_dir():
        raise InputError(where, "is a folder, not a results file")
    # a regular file of an accepted size only: a device (/dev/zero) or a named pipe in its
    # place would fill the memory or block
    data = read_regular_file(path, "results file")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(where, f"cannot read the results file: {exc}") from None
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        raise InputError(where, f"not a JSON document (line {exc.lineno}: {exc.msg})") from None
    except RecursionError:
        raise InputError(where, "the document nests too deeply") from None
    return results_from_document(doc, structure, where, case)


def results_from_document(doc, structure: Structure, where: str = "results",
                          case: str | None = None) -> PictureResults:
    """Arrange a results document already read (a ``to_dict()`` of
    :func:`trussfe.static`) as ``structure``'s nodes and members; as :func:`read_results`,
    with ``where`` naming the document in errors."""
    doc, case = _one_case(doc, where, case)
    members = doc.get("members") if isinstance(doc, dict) else None
    if not isinstance(members, dict):
        raise InputError(where, "has no 'members' table; give the --json document of "
                                "'trussfe static'")
    force = np.empty(structure.n_members)
    comp = np.empty(structure.n_members)
    vm = np.empty(structure.n_members)
    has_vm = True
    for i, mid in enumerate(structure.member_ids):
        entry = members.get(mid)
        if not isinstance(entry, dict) or "axial_force" not in entry:
            raise InputError(where, f"member '{mid}' of the model has no axial_force; are "
                                    "these the results of this model?")
        force[i] = _number(entry["axial_force"], where, f"members.{mid}.axial_force")
        comp[i] = max(-force[i], _largest_compression(entry, where, mid), 0.0)
        if has_vm and "max_von_mises" in entry and entry["max_von_mises"] is not None:
            vm[i] = _number(entry["max_von_mises"], where, f"members.{mid}.max_von_mises")
        else:
            has_vm = False
    unknown = set(members) - set(structure.member_ids)
    if unknown:
        raise InputError(where, f"member '{sorted(unknown)[0]}' is not in the model; are "
                                "these the results of this model?")
    nodes = doc.get("nodes")
    disp = None
    if isinstance(nodes, dict) and any(isinstance(v, dict) and "displacement" in v
                                       for v in nodes.values()):
        disp = np.empty((structure.n_nodes, structure.dim))
        for i, nid in enumerate(structure.node_ids):
            entry = nodes.get(nid)
            u = entry.get("displacement") if isinstance(entry, dict) else None
            if not isinstance(u, list) or len(u) != structure.dim:
                raise InputError(where, f"node '{nid}' of the model has no displacement of "
                                        f"{structure.dim} components")
            disp[i] = [_number(x, where, f"nodes.{nid}.displacement") for x in u]
    command = doc.get("command", "")
    return PictureResults(source=where, command=command if isinstance(command, str) else "",
                          axial_force=force, max_von_mises=vm if has_vm else None,
                          displacement=disp, case=case, compression=comp)


def _largest_compression(entry: dict, where: str, mid: str) -> float:
    """Largest compression (N, positive) of a member's ``end_forces`` and ``stations`` in a
    static document, −inf where it gives neither; as
    :func:`trussfe.fem.buckling.largest_compression` of the result the document was written
    from."""
    values = []
    ends = entry.get("end_forces")
    if isinstance(ends, dict):
        for end in ("start", "end"):
            f = ends.get(end)
            if isinstance(f, dict) and "N" in f:
                values.append(_number(f["N"], where, f"members.{mid}.end_forces.{end}.N"))
    stations = entry.get("stations")
    if isinstance(stations, dict) and isinstance(stations.get("N"), list):
        values += [_number(x, where, f"members.{mid}.stations.N") for x in stations["N"]]
    return -min(values) if values else -np.inf


def _one_case(doc, where: str, case: str | None) -> tuple[dict, str | None]:
    """The single-case part of a results document and the name of its case.

    A load-case document (``cases`` and ``combinations``, docs/json.md) holds one result per
    case and combination: ``case`` names the one to draw (a case, else a combination of that
    name).  A single-case document is drawn as it is; a ``case`` given with it must be the one
    it was solved for."""
    if not isinstance(doc, dict):
        return doc, case
    cases = doc.get("cases") if isinstance(doc.get("cases"), dict) else {}
    combos = doc.get("combinations") if isinstance(doc.get("combinations"), dict) else {}
    if "members" not in doc and (cases or combos):
        names = list(cases) + [n for n in combos if n not in cases]
        if case is None:
            raise InputError(where, "holds the results of several load cases: choose one with "
                                    f"--case NAME (one of {', '.join(names)})")
        part = cases.get(case, combos.get(case))
        if not isinstance(part, dict):
            raise InputError(where, f"has no load case or combination '{case}' (it holds "
                                    f"{', '.join(names)})")
        return {"command": doc.get("command", ""), **part}, case
    solved = doc.get("case", doc.get("combination"))
    if case is not None and solved != case:
        held = f"load case '{solved}'" if solved else "the model's loads"
        raise InputError(where, f"holds the results of {held}, not of load case '{case}'; "
                                "write 'trussfe static --all' results to choose a case")
    return doc, case if case is not None else solved


def utilisation(structure: Structure, results: PictureResults) -> np.ndarray:
    """Utilisation of every member: the larger of the stress ratio (largest von Mises stress
    over the yield strength, where the material gives one) and the buckling ratio
    (the largest compression along the member over its Euler load, Lacy eq. 2.26 with pinned
    ends, K = 1).

    Parameters
    ----------
    structure : Structure
    results : PictureResults

    Returns
    -------
    ndarray, shape (m,)
        1 is the limit; NaN where neither ratio is known (no yield strength and no bending
        stiffness).

    Examples
    --------
    A 2 m tube of Lacy Table 3.3 (Euler load 1481.2 N) in 740.6 N compression is half used:

    >>> import numpy as np, trussfe
    >>> s = trussfe.model_from_dict({"model": {"dimension": 2},
    ...     "materials": {"al": {"E": 71e9}},
    ...     "sections": {"t": {"outer_diameter": 0.0254, "inner_diameter": 0.022225}},
    ...     "nodes": {"A": [0, 0], "B": [2, 0]},
    ...     "members": {"AB": {"nodes": ["A", "B"], "section": "t", "material": "al"}}})
    >>> r = PictureResults("", "static", np.array([-740.6]), None, None)
    >>> np.round(utilisation(s, r), 3)
    array([0.5])
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        comp = (results.compression if results.compression is not None
                else np.maximum(-results.axial_force, 0.0))
        buckling = comp / member_euler_loads(structure)
        stress = (results.max_von_mises / structure.yield_strength
                  if results.max_von_mises is not None else np.full(structure.n_members, np.nan))
    buckling = np.where(np.isfinite(buckling), buckling, np.nan)
    return np.fmax(stress, buckling)


# ---------------------------------------------------------------------- what to draw
@dataclass
class _Scene:
    """Everything of the picture in model coordinates, independent of the renderer."""

    dim: int
    size: float
    base: np.ndarray              # (n, dim) undeformed
    shape: np.ndarray             # (n, dim) drawn (deformed or undeformed)
    conn: np.ndarray
    deformed: bool
    colour_by: str
    values: np.ndarray | None     # (m,) when coloured by a result
    value_label: str
    clim: tuple[float, float]
    cmap: str
    groups: list[tuple[str, np.ndarray]]   # (section name, member mask) when by section
    node_labels: list[str]
    member_labels: list[str]
    supports: dict[str, np.ndarray]        # kind -> node indices
    load_nodes: np.ndarray
    load_vectors: np.ndarray               # (k, dim) drawn arrows
    load_labels: list[str]
    member_load_tips: np.ndarray           # (j, dim) points of action, undeformed
    member_load_vectors: np.ndarray        # (j, dim) drawn arrows
    member_load_labels: list[str]
    title: str


def _scene(structure: Structure, results: PictureResults | None, colour_by: str | None,
           scale: float | None, labels: bool | None) -> _Scene:
    s = structure
    dim = s.dim
    x0 = np.asarray(s.coords, float)
    size = float(np.ptp(x0, axis=0).max()) if s.n_nodes else 1.0
    size = size or 1.0
    if colour_by is None:
        colour_by = "axial_force" if results is not None else "section"
    if colour_by not in COLOR_BY:
        raise InputError("--color", f"unknown colouring '{colour_by}'; use "
                                    + ", ".join(COLOR_BY))
    if colour_by != "section" and results is None:
        raise InputError("--color", f"colouring by {colour_by} needs --results (the --json "
                                    "document of 'trussfe static')")
    title = s.name or "model"
    shape, deformed = x0, False
    if results is not None and results.displacement is not None:
        amp = float(np.linalg.norm(results.displacement, axis=1).max(initial=0.0))
        if scale is None:
            scale = DEFORMED_SIZE * size / amp if amp > 0 else 0.0
        if amp > 0 and scale > 0:
            shape, deformed = x0 + scale * results.displacement, True
            title += f" — deformed shape ×{scale:.3g}"
    if results is not None and results.case:
        title += f" — {results.case}"
    values, label, clim, cmap, groups = None, "", (0.0, 1.0), "coolwarm", []
    if colour_by == "axial_force":
        values = results.axial_force
        vmax = float(np.max(np.abs(values), initial=0.0)) or 1.0
        label, clim = "axial force [N] (tension +)", (-vmax, vmax)
    elif colour_by == "utilisation":
        values = utilisation(s, results)
        top = float(np.nanmax(values)) if np.isfinite(values).any() else 1.0
        label, clim, cmap = "utilisation [-]", (0.0, max(1.0, top)), "RdYlGn_r"
    else:
        names = [sec.name for sec in s.sections]
        for name in dict.fromkeys(names):
            groups.append((name, np.array([n == name for n in names], bool)))
    if labels is None:
        labels = s.n_nodes + s.n_members <= LABEL_LIMIT
    sup = np.asarray(s.supports, bool)
    trans, rot = sup[:, :dim], sup[:, dim:]
    clamp = trans.all(axis=1) & rot.all(axis=1) & (rot.shape[1] > 0)
    pin = trans.all(axis=1) & ~clamp
    roller = trans.any(axis=1) & ~trans.all(axis=1)
    loads = np.asarray(s.loads, float)
    force, moment = loads[:, :dim], loads[:, dim:]
    fmag = np.linalg.norm(force, axis=1)
    mmag = np.linalg.norm(moment, axis=1) if moment.shape[1] else np.zeros(s.n_nodes)
    loaded = np.flatnonzero((fmag > 0) | (mmag > 0))
    point = [np.linalg.norm(ld.force) for ld in (s.extensions.get("member_loads", ()) or ())
             if ld.kind == "point" and ld.force]
    fmax = float(max(fmag.max(initial=0.0), *point, 0.0)) or 1.0
    vectors = LOAD_ARROW * size * force[loaded] / fmax
    load_labels = []
    for i in loaded:
        parts = [f"{fmag[i]:.4g} N"] if fmag[i] > 0 else []
        if mmag[i] > 0:
            parts.append(f"M = {mmag[i]:.4g} N·m")
        load_labels.append(", ".join(parts))
    tips, mvec, mlabels = _member_loads(s, x0, size, fmax)
    return _Scene(dim=dim, size=size, base=x0, shape=shape,
                  conn=np.asarray(s.connectivity, int), deformed=deformed,
                  colour_by=colour_by, values=values, value_label=label, clim=clim,
                  cmap=cmap, groups=groups,
                  node_labels=[str(n) for n in s.node_ids] if labels else [],
                  member_labels=[str(m) for m in s.member_ids] if labels else [],
                  supports={"pin": np.flatnonzero(pin), "roller": np.flatnonzero(roller),
                            "clamp": np.flatnonzero(clamp),
                            "spring": np.flatnonzero(_spring_nodes(s))},
                  load_nodes=loaded, load_vectors=vectors, load_labels=load_labels,
                  member_load_tips=tips, member_load_vectors=mvec,
                  member_load_labels=mlabels, title=title)


def _spring_nodes(s: Structure) -> np.ndarray:
    """Nodes with an elastic support (``springs``) on any DOF, as a mask."""
    springs = s.extensions.get("springs")
    if springs is None:
        return np.zeros(s.n_nodes, bool)
    return np.asarray(springs.stiffness > 0).any(axis=1)


def _member_loads(s: Structure, x0: np.ndarray, size: float, fmax: float
                  ) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """Arrows of the loads along members (``member_loads``): a point force where it acts, in
    the scale of the nodal forces; a distributed load at the member middle, drawn at a fixed
    length in the direction of its mean intensity, labelled with its intensity in N/m."""
    loads = tuple(s.extensions.get("member_loads", ()) or ())
    dim = s.dim
    if not loads:
        return np.zeros((0, dim)), np.zeros((0, dim)), []
    rot = local_axes(s) if any(ld.axes == "local" for ld in loads) else None
    conn = np.asarray(s.connectivity, int)
    tips, vecs, labels = [], [], []
    for ld in loads:                      # a handful of loads per model: labels, not a solve
        a, b = x0[conn[ld.member]]
        if ld.kind == "point":
            at = ld.at
            vec = np.asarray(ld.force, float) if ld.force else np.zeros(dim)
            length = LOAD_ARROW * size * np.linalg.norm(vec) / fmax
            parts = [f"F = {np.linalg.norm(vec):.4g} N"] if np.any(vec) else []
            if ld.moment and np.any(ld.moment):
                parts.append(f"M = {np.linalg.norm(ld.moment):.4g} N·m")
            text = ", ".join(parts)
        else:
            at = 0.5 * (ld.span[0] + ld.span[1])          # the middle of the loaded span
            qs, qe = np.asarray(ld.q_start, float), np.asarray(ld.q_end, float)
            vec = 0.5 * (qs + qe)
            length = 0.6 * LOAD_ARROW * size
            ns, ne = np.linalg.norm(qs), np.linalg.norm(qe)
            text = (f"q = {ns:.4g} N/m" if np.isclose(ns, ne)
                    else f"q = {ns:.4g} to {ne:.4g} N/m")
        if rot is not None and ld.axes == "local":
            vec = rot[ld.member].T @ vec          # member axes to global
        norm = np.linalg.norm(vec)
        tips.append(a + at * (b - a))
        vecs.append(vec / norm * length if norm > 0 else np.zeros(dim))
        labels.append(text)
    return np.array(tips), np.array(vecs), labels


#: Support symbols: (matplotlib marker, face colour, legend text).
_SUPPORT_STYLE = {"pin": ("^", "black", "support: translations fixed"),
                  "roller": ("^", "none", "support: some translations fixed"),
                  "clamp": ("s", "black", "support: clamped (rotations fixed too)"),
                  "spring": ("D", "none", "elastic support (spring)")}
_LOAD_COLOUR = "tab:green"
_MEMBER_LOAD_COLOUR = "darkmagenta"
_SECTION_COLOURS = ("tab:blue", "tab:orange", "tab:purple", "tab:brown", "tab:pink",
                    "tab:olive", "tab:cyan", "tab:red", "tab:gray", "navy")


# ---------------------------------------------------------------------- matplotlib
def _mpl_draw(scene: _Scene, out: Path, size: tuple[int, int]) -> None:
    from matplotlib import cm, colormaps, colors
    from matplotlib.lines import Line2D

    from .figures import new_figure

    three = scene.dim == 3
    fig = new_figure(figsize=(size[0] / 100, size[1] / 100), dpi=100)
    ax = fig.add_subplot(1, 1, 1, projection="3d" if three else None)
    if three:
        from mpl_toolkits.mplot3d.art3d import Line3DCollection as Lines
    else:
        from matplotlib.collections import LineCollection as Lines
    segs = scene.shape[scene.conn]
    if scene.deformed:
        ax.add_collection(Lines(scene.base[scene.conn], colors="0.8", linewidths=1.5))
    handles = []
    if scene.values is not None:
        norm = colors.Normalize(*scene.clim)
        cmap = colormaps[scene.cmap]
        cols = cmap(norm(np.nan_to_num(scene.values, nan=scene.clim[0])))
        cols[~np.isfinite(scene.values)] = colors.to_rgba("0.6")
        ax.add_collection(Lines(segs, colors=cols, linewidths=3.0))
        fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.75,
                     label=scene.value_label)
    else:
        for k, (name, mask) in enumerate(scene.groups):
            col = _SECTION_COLOURS[k % len(_SECTION_COLOURS)]
            ax.add_collection(Lines(segs[mask], colors=col, linewidths=2.5))
            handles.append(Line2D([], [], color=col, lw=2.5, label=f"section {name}"))
    pts = scene.shape
    ax.scatter(*pts.T, s=12, color="black", zorder=3)
    for kind, idx in scene.supports.items():
        if idx.size:
            marker, face, text = _SUPPORT_STYLE[kind]
            ax.scatter(*pts[idx].T, s=160, marker=marker, facecolors=face,
                       edgecolors="black", linewidths=1.5, zorder=4)
            handles.append(Line2D([], [], ls="", marker=marker, markersize=10,
                                  markerfacecolor=face, markeredgecolor="black", label=text))
    off = 0.015 * scene.size
    for i, text in enumerate(scene.node_labels):
        ax.text(*(pts[i] + off), text, fontsize=9, color="black", zorder=5)
    mids = 0.5 * (segs[:, 0] + segs[:, 1])
    for j, text in enumerate(scene.member_labels):
        ax.text(*mids[j], text, fontsize=8, color="0.25", ha="center", va="center", zorder=5,
                bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none",
                      "alpha": 0.75})
    if scene.load_nodes.size:
        tips = pts[scene.load_nodes]
        tails = tips - scene.load_vectors
        if three:
            ax.quiver(*tails.T, *scene.load_vectors.T, color=_LOAD_COLOUR, linewidth=2,
                      arrow_length_ratio=0.25)
        else:
            ax.quiver(*tails.T, *scene.load_vectors.T, color=_LOAD_COLOUR, angles="xy",
                      scale_units="xy", scale=1.0, width=0.006, zorder=6)
        for tail, text in zip(tails, scene.load_labels):
            ax.text(*tail, text, fontsize=9, color=_LOAD_COLOUR, ha="center",
                    va="bottom", zorder=7)
        handles.append(Line2D([], [], color=_LOAD_COLOUR, lw=2, marker=">",
                              label="nodal load"))
    if scene.member_load_labels:
        tails = scene.member_load_tips - scene.member_load_vectors
        vec = scene.member_load_vectors
        if three:
            ax.quiver(*tails.T, *vec.T, color=_MEMBER_LOAD_COLOUR, linewidth=2,
                      arrow_length_ratio=0.25)
        else:
            ax.quiver(*tails.T, *vec.T, color=_MEMBER_LOAD_COLOUR, angles="xy",
                      scale_units="xy", scale=1.0, width=0.005, zorder=6)
        for tail, text in zip(tails, scene.member_load_labels):
            ax.text(*tail, text, fontsize=9, color=_MEMBER_LOAD_COLOUR, ha="center",
                    va="bottom", zorder=7)
        handles.append(Line2D([], [], color=_MEMBER_LOAD_COLOUR, lw=2, marker=">",
                              label="member load"))
    every = np.concatenate([scene.base, scene.shape, pts[scene.load_nodes] - scene.load_vectors,
                            scene.member_load_tips - scene.member_load_vectors])
    lo, hi = every.min(axis=0), every.max(axis=0)
    pad = 0.08 * scene.size
    if three:
        lo, hi = lo - pad, hi + pad
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
        ax.set_zlim(lo[2], hi[2])
        ax.set_box_aspect(tuple(np.maximum(hi - lo, 0.15 * (hi - lo).max())))
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        ax.set_zlabel("z [m]")
    else:
        # a flat model (a beam) still gets room above and below for labels and the legend
        grow = max(0.0, 0.45 * scene.size - float(hi[1] - lo[1])) / 2
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad - grow, hi[1] + pad + grow)
        ax.set_aspect("equal")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        ax.grid(True, color="0.92")
    ax.set_title(scene.title, fontsize=11)
    if handles:
        ax.legend(handles=handles, loc="best", fontsize=8, framealpha=0.85)
    with atomic_path(out) as tmp:
        fig.savefig(tmp, format="png", dpi=100)


# ---------------------------------------------------------------------- pyvista
def _pv_arrows(pv, tails: np.ndarray, vectors: np.ndarray):
    """Arrow glyphs from ``tails`` along ``vectors`` (3-D), each as long as its vector."""
    points = pv.PolyData(tails)
    points["v"] = vectors
    return points.glyph(orient="v", scale="v", factor=1.0,
                        geom=pv.Arrow(tip_length=0.25, tip_radius=0.08, shaft_radius=0.025))


def _pv_draw(scene: _Scene, out: Path, size: tuple[int, int]) -> None:
    import pyvista as pv
    from matplotlib.image import imsave

    def pad3(x: np.ndarray) -> np.ndarray:
        return np.hstack([x, np.zeros((x.shape[0], 3 - x.shape[1]))]) if x.shape[1] < 3 else x

    def lines(points: np.ndarray, conn: np.ndarray):
        cells = np.hstack([np.full((conn.shape[0], 1), 2), conn]).ravel()
        return pv.PolyData(pad3(points), lines=cells)

    p = pv.Plotter(off_screen=True, window_size=list(size))
    try:
        p.set_background("white")
        if scene.deformed:
            p.add_mesh(lines(scene.base, scene.conn), color="lightgrey", line_width=2)
        legend = []
        mesh = lines(scene.shape, scene.conn)
        if scene.values is not None:
            mesh.cell_data[scene.value_label] = np.asarray(scene.values, float)
            p.add_mesh(mesh, scalars=scene.value_label, cmap=scene.cmap, clim=scene.clim,
                       line_width=5, nan_color="grey",
                       scalar_bar_args={"title": scene.value_label, "vertical": True,
                                        "color": "black", "title_font_size": 14,
                                        "label_font_size": 12, "position_x": 0.86,
                                        "position_y": 0.1, "height": 0.7})
        else:
            for k, (name, mask) in enumerate(scene.groups):
                col = _SECTION_COLOURS[k % len(_SECTION_COLOURS)]
                p.add_mesh(lines(scene.shape, scene.conn[mask]), color=col, line_width=5)
                legend.append([f"section {name}", col])
        pts = pad3(scene.shape)
        p.add_mesh(pv.PolyData(pts), color="black", point_size=8,
                   render_points_as_spheres=True)
        glyph = 0.05 * scene.size
        for kind, idx in scene.supports.items():
            if not idx.size:
                continue
            src = (pv.Cube(x_length=glyph, y_length=glyph, z_length=glyph) if kind == "clamp"
                   else pv.Sphere(radius=0.6 * glyph) if kind == "spring"
                   else pv.Cone(direction=(0, 1, 0) if scene.dim == 2 else (0, 0, 1),
                                height=glyph * 1.3, radius=glyph * 0.7, resolution=3))
            where = pts[idx].copy()
            where[:, 1 if scene.dim == 2 else 2] -= 0.6 * glyph
            glyphs = pv.PolyData(where).glyph(geom=src, orient=False, scale=False)
            if kind in ("roller", "spring"):
                p.add_mesh(glyphs, color="black" if kind == "roller" else "saddlebrown",
                           style="wireframe", line_width=2)
            else:
                p.add_mesh(glyphs, color="black")
            legend.append([_SUPPORT_STYLE[kind][2], {"roller": "grey", "spring": "saddlebrown"
                                                     }.get(kind, "black")])
        if scene.load_nodes.size:
            vec = pad3(scene.load_vectors)
            tails = pts[scene.load_nodes] - vec
            p.add_mesh(_pv_arrows(pv, tails, vec), color=_LOAD_COLOUR)
            p.add_point_labels(tails, scene.load_labels, font_size=16,
                               text_color=_LOAD_COLOUR, shape=None, show_points=False,
                               always_visible=True)
            legend.append(["nodal load", _LOAD_COLOUR])
        if scene.member_load_labels:
            vec = pad3(scene.member_load_vectors)
            tails = pad3(scene.member_load_tips) - vec
            drawn = np.linalg.norm(vec, axis=1) > 0
            if drawn.any():
                p.add_mesh(_pv_arrows(pv, tails[drawn], vec[drawn]), color=_MEMBER_LOAD_COLOUR)
            p.add_point_labels(tails, scene.member_load_labels, font_size=16,
                               text_color=_MEMBER_LOAD_COLOUR, shape=None, show_points=False,
                               always_visible=True)
            legend.append(["member load", _MEMBER_LOAD_COLOUR])
        if scene.node_labels:
            off = 0.02 * scene.size
            p.add_point_labels(pts + [off, off, 0.0], scene.node_labels, font_size=14, text_color="black",
                               shape=None, show_points=False, always_visible=True)
        if scene.member_labels:
            mids = 0.5 * (pts[scene.conn[:, 0]] + pts[scene.conn[:, 1]])
            p.add_point_labels(mids, scene.member_labels, font_size=12, text_color="dimgrey",
                               shape_color="white", shape_opacity=0.7, show_points=False,
                               always_visible=True)
        if legend:
            p.add_legend(legend, bcolor="white", face="-", size=(0.3, 0.04 * len(legend)),
                         loc="upper left")
        p.add_text(scene.title, position="upper_edge", font_size=10, color="black")
        if scene.dim == 2:
            p.view_xy()
        else:
            p.view_isometric()
        p.reset_camera()
        p.camera.zoom(0.9 if scene.dim == 2 else 1.05)  # a 3-D model fills less of its sphere
        img = p.screenshot(return_img=True)
    finally:
        p.close()
    with atomic_path(out) as tmp:
        imsave(tmp, img, format="png")


# ---------------------------------------------------------------------- public
def draw_model(path: str | Path, structure: Structure, *, results: PictureResults | None = None,
               color: str | None = None, scale: float | None = None, labels: bool | None = None,
               backend: str | None = None, size: tuple[int, int] = DEFAULT_SIZE) -> str:
    """Draw a model (and its results) to a PNG file.

    Parameters
    ----------
    path : str or Path
        Output PNG.
    structure : Structure
    results : PictureResults, optional
        From :func:`read_results`: members coloured by a result, the deformed shape drawn.
    color : {"section", "axial_force", "utilisation"}, optional
        Default: ``"axial_force"`` with results, ``"section"`` without.
    scale : float, optional
        Magnification of the displacements (default: the largest drawn at
        :data:`DEFORMED_SIZE` of the model size).
    labels : bool, optional
        Write node and member ids (default: when the model has at most :data:`LABEL_LIMIT`
        nodes plus members).
    backend : {"pyvista", "matplotlib"}, optional
        Default :func:`~trussfe.io.render_backend.plot_backend`; a pyvista failure at render
        time falls back to matplotlib.
    size : (int, int)
        Width and height in pixels.

    Returns
    -------
    str
        The backend that drew the picture.
    """
    scene = _scene(structure, results, color, scale, labels)
    out = Path(path)
    chosen = backend or plot_backend()
    if chosen == "pyvista":
        try:
            _pv_draw(scene, out, size)
            return "pyvista"
        except Exception as exc:  # a GL failure at render time: fall back, say why
            log.warning("pyvista rendering failed (%s); using matplotlib", exc)
    _mpl_draw(scene, out, size)
    return "matplotlib"
