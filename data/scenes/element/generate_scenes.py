#!/usr/bin/env python3
"""Writes the bundled element-test scenes of this folder (run from anywhere; rewrites the *.json here).

- ref_*: the reference study's element tests (plane-strain compression of dense Toyoura sand,
  e0 = 0.66, sigma3 = 50 and 200 kPa, bedding angle 0 and 90 deg, ACST and isotropic; drained
  triaxial compression, dense e0 = 0.66 and loose e0 = 0.833, sigma3 = 50 to 400 kPa).
- lab_*: one scene per element-test curve in data/lab/ (TC as drained triaxial compression, PSC as
  plane-strain compression) at the file's sigma3, e0 and bedding angle, overlaying the data.
Parameter sets: the calibrated ones (data/calibration/README.md): toyoura_acst_calibrated.json
(F0 of the air-pluviated Tatsuoka specimens; the Verdugo & Ishihara and Chen & Yang scenes use
their own F0 files) and toyoura_isotropic_calibrated.json. Tests whose e0 is e_0.3 (the void
ratio at 29.4 kPa) start there and are consolidated isotropically to sigma3 before shearing, as
in the calibration. Paths inside a scene are relative to the scene file.
Run them all: acst_element data/scenes/element/*.json
"""
import glob
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
ACST = "../../parameters/toyoura_acst_calibrated.json"
ACST_BY_SOURCE = {"verdugo_ishihara_1996": "../../parameters/toyoura_acst_calibrated_verdugo_ishihara.json",
                  "chen_yang_2025": "../../parameters/toyoura_acst_calibrated_chen_yang.json"}
ISO = "../../parameters/toyoura_isotropic_calibrated.json"
E03_KPA = 29.4  # pressure of e_0.3


def write(name, scene):
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        json.dump(scene, f, indent=2)
        f.write("\n")


def scene(description, material, sigma3, e0, bedding, preset, strain_pct, lab=None, e0_at_kPa=None):
    steps = [{"preset": preset, "axial_strain_pct": strain_pct, "increments": int(round(strain_pct * 100))}]  # 1e-4 per increment
    start = sigma3
    if e0_at_kPa and e0_at_kPa < sigma3:
        steps.insert(0, {"preset": "isotropic_compression", "p_to": sigma3, "increments": 20})
        start = e0_at_kPa
    s = {
        "description": description,
        "material": {"file": material},
        "initial_state": {"confining_pressure": start, "void_ratio": e0, "bedding_angle_deg": bedding},
        "steps": steps,
    }
    if lab:
        s["lab_data"] = lab
    return s


def header(path):
    meta = {}
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            key, _, value = line[1:].strip().partition(":")
            if key and " " not in key:
                meta[key] = value.strip()
    return meta


def main():
    for old in glob.glob(os.path.join(HERE, "*.json")):
        os.remove(old)
    # Reference study: plane-strain compression, dense, anisotropic (bedding 0 and 90) and isotropic.
    for s3 in (50, 200):
        for alpha in (0, 90):
            write(f"ref_psc_dense_s{s3:03d}_a{alpha:02d}_acst",
                  scene(f"Reference study: plane-strain compression (eps_2 = 0, sigma_3 held) of dense Toyoura sand, "
                        f"e0 = 0.66, sigma3 = {s3} kPa, bedding angle {alpha} deg, ACST calibrated set",
                        ACST, s3, 0.66, alpha, "plane_strain_compression", 15))
        write(f"ref_psc_dense_s{s3:03d}_isotropic",
              scene(f"Reference study: plane-strain compression of dense Toyoura sand, e0 = 0.66, sigma3 = {s3} kPa, "
                    f"isotropic model (no bedding dependence: one scene stands for 0 and 90 deg)",
                    ISO, s3, 0.66, 0, "plane_strain_compression", 15))
    # Reference study: drained triaxial compression, dense and loose, 50 to 400 kPa.
    for label, e0 in (("dense", 0.66), ("loose", 0.833)):
        for s3 in (50, 100, 200, 400):
            write(f"ref_tc_{label}_s{s3:03d}_acst",
                  scene(f"Reference study: drained triaxial compression of {label} Toyoura sand, e0 = {e0}, "
                        f"sigma3 = {s3} kPa, bedding angle 0 (load normal to the bedding), ACST calibrated set",
                        ACST, s3, e0, 0, "drained_triaxial_compression", 25))
    # One scene per lab curve.
    for path in sorted(glob.glob(os.path.join(ROOT, "data", "lab", "*", "*.csv"))):
        meta = header(path)
        kind = meta.get("kind", "").split(" ")[0]
        if kind not in ("TC", "PSC") or "strain_range_pct" not in meta:  # curves only, not tables
            continue
        hi = float(meta["strain_range_pct"].split()[1])
        strain = 6.0 if kind == "PSC" else max(5.0, math.ceil(hi * 1.2))
        rel = os.path.relpath(path, HERE)
        caveats = meta.get("caveats", "")
        desc = (f"Lab test {meta['id']} ({meta.get('source', '').split(';')[0]}): "
                f"{'plane-strain' if kind == 'PSC' else 'drained triaxial'} compression at sigma3 = {meta['sigma3_kPa']} kPa, "
                f"e0 = {meta['e0']}, bedding angle {meta.get('bedding_angle_deg', '0')} deg; simulated with the ACST "
                f"calibrated set. e0: {meta.get('e0_definition', '')}. Caveats: {caveats}")
        source = os.path.basename(os.path.dirname(path))
        e03 = E03_KPA if source in ("fukushima_tatsuoka_1984", "lam_tatsuoka_1988") else None
        write("lab_" + meta["id"],
              scene(desc, ACST_BY_SOURCE.get(source, ACST), float(meta["sigma3_kPa"]), float(meta["e0"]),
                    float(meta.get("bedding_angle_deg", 0)),
                    "plane_strain_compression" if kind == "PSC" else "drained_triaxial_compression", strain, rel, e03))


if __name__ == "__main__":
    main()
