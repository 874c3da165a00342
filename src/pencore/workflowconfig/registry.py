"""The Section 4 studies of the workflow, one
:class:`~pencore.workflowconfig.registry.Study` record each.

Everything that names a study is derived from :data:`STUDIES`: the configuration dispatch
(:func:`pencore.studies.config.from_config`, :func:`pencore.studies.config.gather`), the
job parts (:func:`pencore.workflowconfig.parts.parts_of`), the plot table
(:data:`pencore.plotting.PLOTS`) and the workflow's Section 4 rules, their wildcards and
report entries (``workflow/rules/section4*.smk``). Adding a study is adding a record here,
its run function (in :mod:`pencore.studies`) and its plot function (in
:mod:`pencore.plotting`).

Light: the Snakefile reads this module at every start, so it imports nothing heavier than
the standard library (the run and plot functions are named, and imported only when called).
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from pencore.errors import InputError

__all__ = ["Study", "STUDIES", "study", "split_studies", "resolve"]

#: the shared keys of the ``section4`` block (beside the studies' own entries)
SHARED_KEYS = (
    "target",
    "trajectory_samples",
    "speed_fraction",
    "velocity_tol_m_s",
    "omega_tol_rad_s",
    "scan_points",
    "yaw_convention",
    "start_height_m",
)

#: the dimensions a split study's job parts run over, in their order in a part's name
PART_KEYS = ("projectile", "obliquity")


@dataclass(frozen=True)
class Study:
    """One Section 4 study of the workflow.

    Attributes
    ----------
    id : str
        The study's name: ``params.kind`` of its rules, the rule ``s4_<id>_figure``, its
        report caption ``workflow/report/section4_<id>.rst``.
    entry : str
        Its entry of the ``section4`` configuration block (two studies may share one).
    shared : tuple of str
        The shared keys of the ``section4`` block it reads (:data:`SHARED_KEYS`).
    run : str or callable
        ``"module:function"`` (or the function itself) that runs it from
        ``(entry, settings)``: its configuration entry and
        :class:`pencore.studies.config.StudySettings`; returns an ``xarray.Dataset``.
    dataset : str
        Its result, ``results/<dir>/<name>.nc``.
    figure : str
        Its figure without the suffix (``.png`` and ``.pdf`` are written).
    title : str
        The figure's subcategory and label in the workflow report.
    plot : str or callable
        The name of its function in :mod:`pencore.plotting` (or the function itself).
    split_by : tuple of str
        Empty when the study runs as one job; else the :data:`PART_KEYS` its job parts
        run over (a part per projectile, or per projectile and obliquity).
    """

    id: str
    entry: str
    shared: tuple[str, ...]
    run: str | Callable[..., Any]
    dataset: str
    figure: str
    title: str
    plot: str | Callable[..., Any]
    split_by: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        unknown = sorted(set(self.shared) - set(SHARED_KEYS))
        if unknown:
            raise InputError(f"study {self.id!r}: unknown shared keys {unknown}")
        if self.split_by and self.split_by != PART_KEYS[: len(self.split_by)]:
            raise InputError(
                f"study {self.id!r}: split_by {self.split_by} must be a start of {PART_KEYS}"
            )
        if not (self.dataset.startswith("results/") and self.dataset.endswith(".nc")):
            raise InputError(f"study {self.id!r}: dataset {self.dataset!r} is not results/*.nc")

    @property
    def parts_dir(self) -> str:
        """The folder of a split study's job parts: ``<dataset folder>/parts``."""
        return f"{self.dataset.rsplit('/', 1)[0]}/parts"


_TRAJECTORY_KEYS = ("target", "trajectory_samples", "speed_fraction")
_VCR_KEYS = ("target", "velocity_tol_m_s", "scan_points")

#: Study id -> its record, in the workflow's order.
STUDIES: dict[str, Study] = {
    s.id: s
    for s in (
        Study(
            id="fig7",
            entry="fig7",
            shared=_TRAJECTORY_KEYS,
            run="pencore.studies.trajectories.oblique:run_fig7",
            dataset="results/fig7/trajectories.nc",
            figure="results/fig7/fig07_trajectories",
            title="Fig. 07 trajectories and slopes",
            plot="plot_fig7",
        ),
        Study(
            id="fig8",
            entry="fig8",
            shared=_VCR_KEYS,
            run="pencore.studies.critical.vcr:run_fig8",
            dataset="results/fig8/vcr.nc",
            figure="results/fig8/fig08_vcr",
            title="Fig. 08 Vcr vs obliquity",
            plot="plot_fig8",
            split_by=("projectile",),
        ),
        Study(
            id="fig9",
            entry="fig9",
            shared=("target", "trajectory_samples"),
            run="pencore.studies.turning:run_fig9",
            dataset="results/fig9/turning_angle.nc",
            figure="results/fig9/fig09_turning_angle",
            title="Fig. 09 turning angle vs Lc/L",
            plot="plot_fig9",
        ),
        Study(
            id="fig11",
            entry="fig11",
            shared=_TRAJECTORY_KEYS,
            run="pencore.studies.trajectories.yaw:run_fig11",
            dataset="results/fig11/trajectories.nc",
            figure="results/fig11/fig11_trajectories",
            title="Fig. 11 trajectories with yaw",
            plot="plot_fig11",
        ),
        Study(
            id="fig12",
            entry="fig12",
            shared=_VCR_KEYS,
            run="pencore.studies.critical.vcr:run_fig12",
            dataset="results/fig12/vcr_yaw.nc",
            figure="results/fig12/fig12_vcr_yaw",
            title="Fig. 12 Vcr vs yaw",
            plot="plot_fig12",
            split_by=("projectile", "obliquity"),
        ),
        Study(
            id="fig13",
            entry="fig13",
            shared=_TRAJECTORY_KEYS,
            run="pencore.studies.trajectories.yaw:run_fig13",
            dataset="results/fig13/trajectories.nc",
            figure="results/fig13/fig13_trajectories",
            title="Figs 13-14 small yaw, normal impact",
            plot="plot_fig13",
        ),
        Study(
            id="fig15",
            entry="fig15",
            shared=(*_VCR_KEYS, "speed_fraction", "yaw_convention"),
            run="pencore.studies.critical.vci:run_fig15",
            dataset="results/fig15/vci.nc",
            figure="results/fig15/fig15_vci",
            title="Fig. 15 Vci vs Lc/L",
            plot="plot_fig15",
            split_by=("projectile",),
        ),
        Study(
            id="fig16",
            entry="fig16",
            shared=(*_TRAJECTORY_KEYS, "start_height_m"),
            run="pencore.studies.trajectories.spin:run_fig16",
            dataset="results/fig16/trajectories.nc",
            figure="results/fig16/fig16_trajectories",
            title="Figs 16-17 angular velocity",
            plot="plot_fig16",
        ),
        Study(
            id="start_height",
            entry="fig16",
            shared=("target", "speed_fraction"),
            run="pencore.studies.trajectories.spin:run_start_height",
            dataset="results/fig16/start_height.nc",
            figure="results/fig16/fig16_start_height",
            title="Figs 16-17 start-height sensitivity",
            plot="plot_start_height",
        ),
        Study(
            id="fig18",
            entry="fig18",
            shared=("target", "omega_tol_rad_s", "scan_points", "start_height_m"),
            run="pencore.studies.critical.omega_c:run_fig18",
            dataset="results/fig18/omega_c.nc",
            figure="results/fig18/fig18_omega_c",
            title="Fig. 18 omega_c vs Vi",
            plot="plot_fig18",
            split_by=("projectile",),
        ),
    )
}


def study(name: str) -> Study:
    """The record of study ``name``; :class:`~pencore.errors.InputError` if there is none."""
    try:
        return STUDIES[name]
    except KeyError:
        raise InputError(f"unknown Section 4 study {name!r}; known: {', '.join(STUDIES)}") from None


def split_studies() -> dict[str, Study]:
    """The studies that run in job parts (``split_by`` not empty), by id."""
    return {k: s for k, s in STUDIES.items() if s.split_by}


def resolve(ref: str | Callable[..., Any], module: str | None = None) -> Callable[..., Any]:
    """The function a record names: ``ref`` itself if callable, else ``"module:function"``,
    or ``function`` of ``module``. Imports on call, so that reading the registry stays light."""
    if callable(ref):
        return ref
    mod, _, name = ref.rpartition(":")
    return getattr(importlib.import_module(mod or module or ""), name)
