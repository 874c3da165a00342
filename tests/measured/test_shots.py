"""Shot tables (pencore.measured.shots): the shipped tables against their sources' stated
counts, the mapping of measured angles of attack, and the reader's refusals, each one line
naming the file and the row."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pencore.errors import InputError
from pencore.measured.shots import (
    BODY_SHOT_COLUMNS,
    read_body_shot_table,
    read_shot_table,
    total_angle_of_attack,
)

REPO = Path(__file__).resolve().parents[2]
OGIVE = str(REPO / "config" / "aluminium_ogive_shots.csv")
CONCRETE = str(REPO / "config" / "concrete_ogive_shots.csv")
SHOT_HEADER = (
    "shot,projectile,striking_velocity_m_s,depth_m,pitch_deg,yaw_deg,rigid,table,page,source\n"
)


def _csv(tmp_path, text, name="m.csv"):
    p = tmp_path / name
    p.write_text(text)
    return str(p)


def test_total_angle_of_attack():
    assert total_angle_of_attack(2.0, 0.0) == pytest.approx(2.0, rel=1e-14)
    assert total_angle_of_attack(0.0, -3.0) == pytest.approx(3.0, rel=1e-14)
    # tan^2 delta = tan^2 pitch + tan^2 yaw
    d = math.radians(total_angle_of_attack(3.0, 4.0))
    assert math.tan(d) ** 2 == pytest.approx(
        math.tan(math.radians(3.0)) ** 2 + math.tan(math.radians(4.0)) ** 2, rel=1e-12
    )


def test_shot_table_maps_angles_to_a_normal_velocity():
    df = read_shot_table(OGIVE)
    assert len(df) == 34
    # the velocity is along the normal: obliquity + yaw = 0, the axis tilted by delta
    assert np.allclose(df["obliquity_deg"] + df["yaw_deg"], 0.0, atol=1e-14)
    row = df.set_index("test").loc["4-1805"]  # pitch 3.0 U, yaw 2.0 R
    assert row["obliquity_deg"] == pytest.approx(total_angle_of_attack(3.0, 2.0))
    # "---" (not measured) is no angle; the shot is kept
    assert df.set_index("test").loc["1-0412", "obliquity_deg"] == 0.0
    # the three shots with only a channel length are kept, with no measured depth
    assert sorted(df.loc[df["unmeasured"], "test"]) == ["4-1810", "8-0117", "8-0118"]
    assert df.loc[df["unmeasured"], "measured_depth_m"].isna().all()
    assert df["source"].str.contains(r"Table [12], p\. 72[56]").all()


@pytest.mark.parametrize(
    "row, needle",
    [
        ("1,p2,300,0.1,0,0,maybe,1,5,src", "rigid must be true or false"),
        ("1,p2,300,0.1,50,0,true,1,5,src", "pitch_deg must be a number in"),
        ("1,p2,-300,0.1,0,0,true,1,5,src", "striking_velocity_m_s must be a finite number > 0"),
        ("1,p2,300,0.1,0,0,true,,5,src", "no table"),
    ],
)
def test_shot_table_refusals_name_the_row(tmp_path, row, needle):
    with pytest.raises(InputError, match=needle) as e:
        read_shot_table(_csv(tmp_path, SHOT_HEADER + row + "\n"))
    assert "row 1 (shot 1)" in str(e.value)


def test_duplicate_shots_refused(tmp_path):
    text = SHOT_HEADER + "1,p2,300,0.1,0,0,true,1,5,s\n1,p2,310,0.1,0,0,true,1,5,s\n"
    with pytest.raises(InputError, match="duplicate shots"):
        read_shot_table(_csv(tmp_path, text))


# ------------------------------------------------------------ the concrete body shot table

#: Rows per set as the compilation holds them (Data.xlsx; the file's header states the same
#: counts): Forrestal et al. 1994 [9] 15 rows, 1996 [20] 41, 2003 [8] 17, Frew et al. 2006
#: [10] 23, Gran & Frew 1997 [15] 3, O'Neil et al. 1999 [55] 8.
CONCRETE_SETS = {
    "forrestal1994_d76.2_crh3_fc23": 6,
    "forrestal1994_d76.2_crh3_fc39": 5,
    "forrestal1994_d76.2_crh6_fc23": 2,
    "forrestal1994_d76.2_crh6_fc39": 2,
    "forrestal1996_d12.9_crh3_fc13.5": 6,
    "forrestal1996_d12.9_crh4.25_fc13.5": 5,
    "forrestal1996_d12.9_crh3_fc19.5": 2,
    "forrestal1996_d12.9_crh3_fc21.6": 6,
    "forrestal1996_d12.9_crh4.5_fc21.6": 6,
    "forrestal1996_d20.3_crh3_fc62.8": 6,
    "forrestal1996_d30.5_crh3_fc51": 10,
    "forrestal2003_d26.9_crh2_fc32-40": 11,
    "forrestal2003_d26.9_crh2_fc90-108": 6,
    "frew2006_d20.3_crh3_fc58.7": 8,
    "frew2006_d30.5_crh3_fc58.7": 8,
    "frew2006_d76.2_crh3_fc23": 7,
    "gran1997_d27.94_crh3_fc43": 3,
    "oneil1999_d26.9_crh2_fc155-163": 8,
}


@pytest.fixture(scope="module")
def concrete():
    return read_body_shot_table(CONCRETE)


def test_concrete_table_has_the_compilations_rows(concrete):
    assert concrete["set"].value_counts().to_dict() == CONCRETE_SETS
    # every row of the six references, by the compilation's Number (column A)
    numbers = sorted(int(r) for r in concrete["row"])
    expect = [*range(39, 94), *range(165, 168), *range(236, 277), *range(541, 549)]
    assert numbers == expect
    assert (concrete["xlsx_row"] == concrete["row"].astype(int) + 1).all()
    refs = concrete.groupby("reference_key")["row"].count().to_dict()
    assert refs == {
        "Forrestal[8]": 17,
        "Forrestal[9]": 15,
        "Frew[10]": 23,
        "Gran[15]": 3,
        "Hanchak & Forrestal[20]": 41,
        "O’Neil[55]": 8,
    }


def test_concrete_table_sets_are_one_projectile_and_target(concrete):
    for name, g in concrete.groupby("set"):
        assert g["diameter_m"].nunique() == 1 and g["crh"].nunique() == 1, name
        assert g["reference"].nunique() == 1, name
        d_mm = float(name.split("_d")[1].split("_")[0])
        assert g["diameter_m"].iloc[0] == pytest.approx(d_mm / 1e3, rel=1e-12)


def test_concrete_table_fig5_grout_shots(concrete):
    # the 11 shots of the 12.9 mm, 0.064 kg, 88.9 mm rods into 13.5 MPa grout (CRH 3: 6,
    # CRH 4.25: 5); X/d from 8.5 to 66.7
    g = concrete[(concrete["fc_pa"] == 13.5e6) & (concrete["diameter_m"] == 0.0129)]
    assert len(g) == 11
    assert sorted(g["crh"].value_counts().items()) == [(3.0, 6), (4.25, 5)]
    assert (g["mass_kg"] == 0.064).all() and (g["length_m"] == 0.0889).all()
    xd = g["depth_m"] / g["diameter_m"]
    assert xd.min() == pytest.approx(8.53, abs=0.01) and xd.max() == pytest.approx(66.67, abs=0.01)
    # M / (rho d^3) = 15.2 with the paper's grout density 1960 kg/m3 (14.9 with the
    # compiler's 2000): the number Li & Chen quote
    assert 0.064 / (1960 * 0.0129**3) == pytest.approx(15.2, abs=0.05)


def test_concrete_table_strengths(concrete):
    # the docs: O'Neil et al.'s 155-163 MPa lie beyond the 13.5-108 MPa of every other set
    oneil = concrete["reference_key"] == "O’Neil[55]"
    fc = concrete["fc_pa"] / 1e6
    assert (fc[oneil].min(), fc[oneil].max()) == (155.0, 163.0)
    assert fc[~oneil].min() == 13.5 and 108 <= fc[~oneil].max() < 109


def test_concrete_table_li_chen_shot(concrete):
    # the 26.9 mm shot Li & Chen (2003) quote: 277 m/s, 173 mm
    row = concrete.set_index("row").loc["52"]
    assert (row["diameter_m"], row["striking_velocity_m_s"], row["depth_m"]) == (
        0.0269,
        277.0,
        0.173,
    )


BODY_HEADER = ",".join(BODY_SHOT_COLUMNS) + "\n"
BODY_ROW = "7,s1,ref,0.064,0.0129,0.0889,3,2000,13500000,590,0.31"


def test_body_table_reads_a_good_row(tmp_path):
    df = read_body_shot_table(_csv(tmp_path, BODY_HEADER + BODY_ROW + "\n"))
    assert df.loc[0, "mass_kg"] == 0.064 and df.loc[0, "row"] == "7"


@pytest.mark.parametrize(
    "text, needle",
    [
        ("", "holds no table .it is empty or only comments."),
        ("# provenance only\n# nothing else\n", "holds no table .it is empty or only comments."),
        (BODY_HEADER, "has no rows"),
        ("row,set\n1,a\n", "lacks column"),
    ],
)
def test_body_table_refuses_empty_files(tmp_path, text, needle):
    with pytest.raises(InputError, match=needle):
        read_body_shot_table(_csv(tmp_path, text))


@pytest.mark.parametrize(
    "row, needle",
    [
        ("fast", "striking_velocity_m_s must be a finite number > 0 (m/s), got 'fast'"),
        ("-590", "striking_velocity_m_s must be a finite number > 0 (m/s), got -590"),
        ("", "striking_velocity_m_s must be a finite number > 0 (m/s), got nan"),
        ("inf", "striking_velocity_m_s must be a finite number > 0"),
    ],
)
def test_body_table_text_cell_names_the_row(tmp_path, row, needle):
    good = BODY_ROW.replace(",7,", ",8,").replace("7,s1", "8,s1", 1)
    bad = BODY_ROW.replace("7,s1", "9,s1", 1).replace(",590,", f",{row},")
    text = BODY_HEADER + good + "\n" + bad + "\n"
    with pytest.raises(InputError) as e:
        read_body_shot_table(_csv(tmp_path, text))
    assert f"row 2 (row 9): {needle}" in str(e.value)
    assert "\n" not in str(e.value)


def test_body_table_refuses_duplicate_rows_and_missing_set(tmp_path):
    text = BODY_HEADER + BODY_ROW + "\n" + BODY_ROW + "\n"
    with pytest.raises(InputError, match=r"duplicate rows \['7'\]"):
        read_body_shot_table(_csv(tmp_path, text))
    with pytest.raises(InputError, match=r"row 1 \(row 7\): no set"):
        read_body_shot_table(_csv(tmp_path, BODY_HEADER + BODY_ROW.replace("s1", "") + "\n"))


def test_no_such_file():
    with pytest.raises(InputError, match="no such file"):
        read_body_shot_table("/nonexistent/shots.csv")


def test_concrete_numbers_are_positive(concrete):
    num = concrete[[c for c in BODY_SHOT_COLUMNS if c not in ("row", "set", "reference")]]
    assert np.isfinite(num.to_numpy()).all() and (num.to_numpy() > 0).all()
    assert isinstance(concrete, pd.DataFrame) and not math.isnan(concrete["depth_m"].sum())
