# Configuration helpers of the Section 4 rules (workflow/rules/section4.smk); no rules here.
from pencore.studies.parts import parts_of

S4 = config["section4"]

# shared keys of the section4 block read by each study (the rest is the study's own entry)
S4_SHARED = {
    "fig7": ["target", "trajectory_samples", "speed_fraction"],
    "fig8": ["target", "velocity_tol_m_s", "scan_points"],
    "fig9": ["target", "trajectory_samples"],
    "fig11": ["target", "trajectory_samples", "speed_fraction"],
    "fig12": ["target", "velocity_tol_m_s", "scan_points"],
    "fig13": ["target", "trajectory_samples", "speed_fraction"],
    "fig15": ["target", "velocity_tol_m_s", "scan_points", "speed_fraction", "yaw_convention"],
    "fig16": ["target", "trajectory_samples", "speed_fraction", "start_height_m"],
    "start_height": ["target", "speed_fraction"],
    "fig18": ["target", "omega_tol_rad_s", "scan_points", "start_height_m"],
}
# study -> (config entry, output dataset)
S4_DATASETS = {
    "fig7": ("fig7", "results/fig7/trajectories.nc"),
    "fig8": ("fig8", "results/fig8/vcr.nc"),
    "fig9": ("fig9", "results/fig9/turning_angle.nc"),
    "fig11": ("fig11", "results/fig11/trajectories.nc"),
    "fig12": ("fig12", "results/fig12/vcr_yaw.nc"),
    "fig13": ("fig13", "results/fig13/trajectories.nc"),
    "fig15": ("fig15", "results/fig15/vci.nc"),
    "fig16": ("fig16", "results/fig16/trajectories.nc"),
    "start_height": ("fig16", "results/fig16/start_height.nc"),
    "fig18": ("fig18", "results/fig18/omega_c.nc"),
}
S4_FIGURE_TITLES = {
    "fig7": "Fig. 07 trajectories and slopes",
    "fig8": "Fig. 08 Vcr vs obliquity",
    "fig9": "Fig. 09 turning angle vs Lc/L",
    "fig11": "Fig. 11 trajectories with yaw",
    "fig12": "Fig. 12 Vcr vs yaw",
    "fig13": "Figs 13-14 small yaw, normal impact",
    "fig15": "Fig. 15 Vci vs Lc/L",
    "fig16": "Figs 16-17 angular velocity",
    "start_height": "Figs 16-17 start-height sensitivity",
    "fig18": "Fig. 18 omega_c vs Vi",
}


def s4_params(study):
    """Config slice of one study: its entry, the shared keys it reads, numerics."""
    entry, _ = S4_DATASETS[study]
    return {
        "study": canonical(S4[entry]),
        "shared": canonical({key: S4[key] for key in S4_SHARED[study]}),
        "numerics": canonical(config["numerics"]),
    }


def s4_part_name(part):
    if "obliquity" in part:
        return f"{part['projectile']}_{part['obliquity']:g}"
    return part["projectile"]


def s4_parts(study):
    return [f"results/{study}/parts/{s4_part_name(p)}.nc" for p in parts_of(study, S4[study])]


def s4_figure_path(study, ext):
    """results/<dir>/figNN_<dataset stem>.<ext>: unique file names across the report."""
    entry, dataset = S4_DATASETS[study]
    directory, stem = dataset.rsplit("/", 1)
    return f"{directory}/fig{int(entry[3:]):02d}_{stem.removesuffix('.nc')}.{ext}"
