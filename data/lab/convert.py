#!/usr/bin/env python3
"""Convert the shared Toyoura-sand laboratory data into the project's data/lab format.

Usage (from anywhere):
    python3 data/lab/convert.py [SOURCE_DIR]

SOURCE_DIR defaults to ../../../shared/data relative to this file (i.e. <repo>/../shared/data).
Writes everything under the folder that holds this script (data/lab/), overwriting earlier
output, so the script can be re-run at will. Standard library only.

What it does (see data/lab/README.md, which it also writes):
  * element-test curves (TC, PSC) -> data/lab/<source_folder>/<id>.csv with `# key: value`
    headers and the columns eps_a_pct,stress_ratio,q_kPa,eps_v_pct (PSC files keep the
    source's extra column s2_over_s3 at the end);
  * Chen & Yang (2025) files: the padded flat tail (rows after the last change of value) is cut,
    and the cut point is checked against the one stated in the source README;
  * Kimura et al. (1985) load-settlement curves, one file per test, plus tests_meta.csv;
  * Lam & Tatsuoka (1988) Fig. 21(a)/(b) tables and Fukushima & Tatsuoka (1984) Table 1;
  * a read-back check of every file written (row counts, verbatim values, no filled gaps).
"""

import csv
import io
import os
import re
import sys

KEY_RE = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")
HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SRC = os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared", "data"))

# --------------------------------------------------------------------------------------------
# Citations and fixed texts
# --------------------------------------------------------------------------------------------
CIT_FT84 = ("Fukushima, S. and Tatsuoka, F. (1984). Strength and deformation characteristics of "
            "saturated sand at extremely low pressures. Soils and Foundations 24(4):30-48")
CIT_LT88 = ("Lam, W.-K. and Tatsuoka, F. (1988). Effects of initial anisotropic fabric and sigma2 on "
            "strength and deformation characteristics of sand. Soils and Foundations 28(1):89-106")
CIT_VI96 = ("Verdugo, R. and Ishihara, K. (1996). The steady state of sandy soils. "
            "Soils and Foundations 36(2):81-91")
CIT_CY25 = ("Chen and Yang (2025). Engineering Geology 345:107863 (University of Hong Kong; "
            "full title and author names are not given in the source files)")
CIT_K85 = ("Kimura, T., Kusakabe, O. and Saitoh, K. (1985). Geotechnical model tests of bearing "
           "capacity problems in a centrifuge. Geotechnique 35(1):33-45")
CIT_WANG = ("Wang sand triaxial database, rev. 2, 4TU.ResearchData, "
            "doi:10.4121/086847a6-ba39-4d66-973b-6b93028c7ad8; licence CC-BY-4.0 (cite the database "
            "and the original paper)")
DB_THIRD = "digitised by a third party from the figure; research use with citation"
DB_THIRD_TABLE = ("transcribed by a third party from the printed table; research use with "
                  "citation")

SIGN_CURVE = ("compression positive: eps_a_pct > 0 = axial shortening; eps_v_pct > 0 = "
              "contraction, < 0 = dilation. The source files state eps_v 'dilation negative', "
              "which is the same convention, so eps_v values are copied unchanged")
COLUMNS_CURVE = ("eps_a_pct = axial (major principal) strain [%], compression positive | "
                 "stress_ratio = sigma1'/sigma3' [-] | q_kPa = (stress_ratio - 1) * sigma3_kPa "
                 "= sigma1' - sigma3' [kPa], derived here | eps_v_pct = volumetric strain [%], "
                 "contraction positive | an empty cell = no value digitised at that strain "
                 "(never zero): interpolate each column on its own")
COLUMNS_PSC_EXTRA = (" | s2_over_s3 = sigma2'/sigma3' [-] (extra column of the source, "
                     "plane strain only; rows with only this column filled). In PSC q_kPa is "
                     "sigma1' - sigma3', NOT the invariant q (sigma2' != sigma3')")

BEDDING_FT84 = ("assumption: the load is normal to the bedding planes (specimen air-pluviated "
                "vertically into a vertical mould and loaded axially); the paper gives no angle")
BEDDING_WANG = ("assumption: the load is normal to the bedding planes, as for a specimen built "
                "in horizontal layers (e.g. air-pluviated) in a vertical mould and loaded axially; "
                "the preparation method is not given in the database files")
BEDDING_LT88 = ("omega of the paper = angle between sigma1' and the deposition direction "
                "(0: sigma1' normal to the bedding planes) = the project's bedding angle alpha")

# Chen & Yang cut points stated in the source README (last real eps_a, %).
CY_README_CUT = {"wang33_HKU_TMD1": 3.3, "wang33_HKU_TMD3": 3.3, "wang33_HKU_TMD6": 4.4,
                 "wang33_HKU_TMD7": 8.4, "wang33_HKU_TMD5": 9.9}

CURVE_FOLDERS = ["fukushima_tatsuoka_1984", "lam_tatsuoka_1988", "verdugo_ishihara_1996",
                 "chen_yang_2025"]

# Keys of the source headers that are taken over by the project keys (not copied as such).
CONSUMED = {"id", "kind", "sigma3_kPa", "e0", "e0_definition", "source", "eps_v_convention",
            "eps_a_sign", "units", "uncertainty", "caveat_membrane", "caveat_bedding_error",
            "extra_columns"}


# --------------------------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------------------------
def read_commented_csv(path):
    """Return (ordered list of (key, value) from '# key: value' lines, free comment lines,
    column names, rows as lists of strings)."""
    keys, comments, data_lines = [], [], []
    with open(path, newline="") as fh:
        for line in fh:
            if line.startswith("#"):
                body = line[1:].strip()
                k, sep, v = body.partition(":")
                if sep and KEY_RE.match(k):
                    keys.append((k, v.strip()))
                else:
                    comments.append(body)
            elif line.strip():
                data_lines.append(line)
    rows = list(csv.reader(data_lines))
    return keys, comments, rows[0], rows[1:]


def fnum(s):
    return float(s)


def fmt(x, nd=4):
    s = ("%." + str(nd) + "f") % x
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def norm_zero(s):
    """'-0' / '-0.0' -> '0' (a signed zero carries no information)."""
    if s and s.startswith("-") and fnum(s) == 0.0:
        return s[1:]
    return s


def write_file(path, header, columns, rows):
    """header: list of (key, value); rows: list of lists of strings."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    buf = io.StringIO()
    for k, v in header:
        v = " ".join(str(v).split())          # one line per key
        buf.write("# %s: %s\n" % (k, v))
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(columns)
    for r in rows:
        w.writerow(r)
    with open(path, "w", newline="") as fh:
        fh.write(buf.getvalue())


def series_range(rows, j):
    """eps_a range of the non-empty cells of column j, excluding the start row(s) at eps_a = 0."""
    e = [fnum(r[0]) for r in rows if len(r) > j and r[j] != "" and fnum(r[0]) > 0]
    return (min(e), max(e)) if e else (None, None)


def first_sr(rows):
    return [r[1] for r in rows if r[1] != "" and fnum(r[0]) > 0][0]


def ev_extremes(rows, j_ev):
    ev = [(fnum(r[j_ev]), fnum(r[0])) for r in rows if r[j_ev] != ""]
    mn = min(ev)
    mx = max(ev)
    return mn, mx, ev[-1]


# --------------------------------------------------------------------------------------------
# element-test curves
# --------------------------------------------------------------------------------------------
def chen_yang_cut(tid, rows):
    """Index of the last row whose (sr, eps_v) differs from the row before; rows after it are
    the padded tail. Returns (kept_rows, cut_rows, cut_eps, notes)."""
    last = 0
    for i in range(1, len(rows)):
        if rows[i][1:] != rows[i - 1][1:]:
            last = i
    kept, cut = rows[:last + 1], rows[last + 1:]
    cut_eps = fnum(rows[last][0])
    expected = CY_README_CUT.get(tid)
    if expected is None or abs(expected - cut_eps) > 1e-9:
        raise SystemExit("Chen & Yang %s: detected last real point %.4g %% but README says %s %%"
                         % (tid, cut_eps, expected))
    # every cut row must repeat the last kept row exactly
    for r in cut:
        if r[1:] != kept[-1][1:]:
            raise SystemExit("Chen & Yang %s: cut row %s is not a repeat" % (tid, r))
    # single-series flats inside the kept part (one series already constant before the cut)
    notes = []
    for j, name in ((1, "stress_ratio"), (2, "eps_v_pct")):
        lc = max([i for i in range(1, len(kept)) if kept[i][j] != kept[i - 1][j]], default=0)
        if lc < len(kept) - 1:
            notes.append("%s is unchanged (%s) from eps_a %s %% to the cut at %s %% (%d kept row(s)): "
                         "this may already be the start of that series' padding; values kept"
                         % (name, kept[lc][j], kept[lc][0], kept[-1][0], len(kept) - 1 - lc))
    return kept, cut, cut_eps, notes


def convert_curve(folder, fname, src_dir, out_dir, log):
    path = os.path.join(src_dir, folder, fname)
    keys, comments, cols, rows = read_commented_csv(path)
    h = dict(keys)
    tid = h["id"]
    if h.get("eps_v_convention") != "dilation_negative" or h.get("eps_a_sign") != "1":
        raise SystemExit("%s: unexpected sign convention in the source header" % path)
    if cols[:3] != ["eps_a_pct", "sr", "eps_v_pct"]:
        raise SystemExit("%s: unexpected columns %s" % (path, cols))
    extra = cols[3:]
    n_src = len(rows)
    kind = {"TC": "TC", "PS": "PSC", "PSC": "PSC"}[h["kind"]]
    sigma3 = fnum(h["sigma3_kPa"])

    caveats = []
    cut_info = None
    strain_lo = None
    strain_hi = None
    if folder == "chen_yang_2025":
        rows, cut, cut_eps, notes = chen_yang_cut(tid, rows)
        cut_info = (n_src, len(rows), len(cut), cut_eps, cut[0][0] if cut else None,
                    cut[-1][0] if cut else None)
        caveats.append("PADDED source file: the values repeat unchanged after eps_a = %s %%; the "
                       "%d padded rows from %s to %s %% were cut (detected as the rows after the "
                       "last change of value, matching the cut point in the source README); the "
                       "test is only known up to %s %%"
                       % (fmt(cut_eps), len(cut), cut[0][0], cut[-1][0], fmt(cut_eps)))
        caveats.extend(notes)
        srs = [fnum(r[1]) for r in rows]
        if srs.index(max(srs)) >= len(srs) - 3:
            caveats.append("the stress ratio is still rising (or just flat) at the last real point "
                           "(%s at eps_a %s %%): the peak is NOT reached in these data; the copied "
                           "key peak_at_end_of_test: false was set by the database on the padded "
                           "file" % (rows[-1][1], rows[-1][0]))

    # ---- build output rows (verbatim strings, signed zeros normalised, q derived) ----
    out = []
    for r in rows:
        r = r + [""] * (len(cols) - len(r))
        ea, sr, ev = norm_zero(r[0]), r[1], norm_zero(r[2])
        q = fmt((fnum(sr) - 1.0) * sigma3) if sr != "" else ""
        out.append([ea, sr, q, ev] + [norm_zero(x) for x in r[3:]])
    out.sort(key=lambda x: fnum(x[0]))           # stable: ties keep the source order

    # ---- ranges, peak, sign check ----
    sr_lo, sr_hi = series_range(out, 1)
    ev_lo, ev_hi = series_range(out, 3)
    (ev_min, ea_min), (ev_max, ea_max), (ev_last, ea_last) = ev_extremes(out, 3)
    e_all = [fnum(r[0]) for r in out if fnum(r[0]) > 0]
    is_wang = folder in ("verdugo_ishihara_1996", "chen_yang_2025")
    strain_lo = 0.0 if is_wang else min(e_all)
    strain_hi = max(e_all)
    if kind == "PSC":
        strain_hi = fnum(h["eps_peak_pct"])
    sign_check = ("eps_v in this file: min %s %% at eps_a %s %%, max %s %% at eps_a %s %%, last %s "
                  "%% at eps_a %s %%; " % (fmt(ev_min), fmt(ea_min), fmt(ev_max), fmt(ea_max),
                                           fmt(ev_last), fmt(ea_last)))
    if ev_min < -0.5:
        sign_check += ("the specimen ends dilating (negative eps_v at large strain), as a dense "
                       "specimen must in the compression-positive convention")
    else:
        sign_check += ("the specimen stays contractive (positive eps_v), as a loose specimen "
                       "does in the compression-positive convention")

    # ---- caveats per source ----
    first_row = out[0]
    start_txt = ("the first row %s is the assumed isotropic start, not a measured point"
                 % ",".join(x for x in [first_row[0], first_row[1], first_row[3]]))
    if folder == "fukushima_tatsuoka_1984":
        caveats += [
            "e0 is e_0.3, the void ratio at 29.4 kPa (the paper's density label), NOT the void ratio "
            "at the shearing stress, which the paper does not report",
            "stress ratios are mid-height values NOT corrected for membrane forces (matters at very "
            "low sigma3; biased at sigma_c' <= 9.8 kPa)",
            "sigma3' drifted during the test: " + h.get("sigma3_f_kPa", "n/a") +
            " kPa at failure vs the nominal sigma3_kPa; q_kPa uses the nominal value",
            "the initial rise of the stress ratio (below about 1 %% axial strain) was not "
            "digitised: the first point is at eps_a %s %% with stress_ratio %s already; "
            "small-strain stiffness cannot be fitted from this file; interpolating between the "
            "start row and the first point is not data" % (fmt(sr_lo), first_sr(out)),
            "rows fill ONE of stress_ratio / eps_v_pct (two traces digitised at different strains)",
            start_txt,
        ]
        if sigma3 < 29.4:
            caveats.append("sheared below 29.4 kPa: e_0.3 was estimated by the authors from the "
                           "consolidation curve (p. 35)")
        uncertainty = h["uncertainty"]
        source = "%s; %s" % (CIT_FT84, h["source"].split("Fukushima & Tatsuoka (1984) Soils and "
                                                          "Foundations 24(4):30-48, ")[-1])
        database = DB_THIRD
        bedding, bedding_note = 0, BEDDING_FT84
    elif folder == "lam_tatsuoka_1988":
        caveats += [
            "e0 is e_0.3, the void ratio at 29.4 kPa (legend); the specimen was then consolidated "
            "to 98 kPa and the void ratio at shearing is NOT reported (lower by an unknown amount)",
            "eps_a converted from the paper's abscissa D = eps1 - eps3 (see x_conversion); "
            "strains not corrected for bedding error at the lubricated ends: eps_a overestimated",
            "initial rise (D < about 2 %%) of the stress ratio not resolved: the first point is "
            "at eps_a %s %% with stress_ratio %s already" % (fmt(sr_lo), first_sr(out)),
            "rows fill ONE of stress_ratio / eps_v_pct (several eps_a values repeat: one row per "
            "series)",
            start_txt,
            "phi_peak_deg / eps_peak_pct are derived from the digitised markers (the true maximum "
            "may lie between markers); these specimens (e_0.3 %s) are denser than the e_0.3 = 0.70 "
            "of the Fig. 21 phi tables" % h["e0"],
        ]
        if tid == "lt88_fig5a_w60_hw1p0":
            # sigma1'/sigma3' below 1 is impossible in drained TC with sigma3' held.
            strain_hi = 13.0
            caveats.insert(0, "the last two stress-ratio markers (2.01 at eps_a 13.92 %, 0.80 at "
                              "14.80 %) are not physical for drained TC with sigma3' held (a ratio "
                              "below 1): a read-out error or the collapse after failure; values "
                              "kept, strain_range_pct ends at 13 % before them")
        if kind == "PSC":
            caveats.insert(0, "strain localises soon after the peak: use up to the peak only "
                              "(strain_range_pct ends at eps_peak_pct = %s %%)" % h["eps_peak_pct"])
            caveats.append("eps_v for D < 8 % is the centre line of the overlapped eps_v band of "
                           "BOTH PSC tests (H/W 1.0 and 1.9), not this test alone; it steps from "
                           "+0.22 % at eps_a 1.36 % to -0.26 % at 1.37 % (a jump in the band "
                           "read-out, not physics): treat eps_v below about 1.4 % with caution")
            caveats.append("s2_over_s3 has 4 markers only (curves overlap for D = 6-11 %); b at "
                           "failure 0.20-0.34 (Fig. 8a)")
        uncertainty = h["uncertainty"]
        source = "%s; %s" % (CIT_LT88, h["source"].split("Lam & Tatsuoka (1988) Soils and "
                                                         "Foundations 28(1):89-106, ")[-1])
        database = DB_THIRD
        bedding, bedding_note = int(h["omega_deg"]), BEDDING_LT88
    else:
        paper = CIT_VI96 if folder == "verdugo_ishihara_1996" else CIT_CY25
        caveats += [
            "e0 is the void ratio after isotropic consolidation, at the start of shearing (database)",
            "digitised by the database compilers from published figures and resampled at 0.1 % "
            "axial strain; tolerance not stated",
            "database material constants for this file: " + h.get("material", ""),
            "the first row (eps_a = 0, stress_ratio = 1, eps_v = %s) is the isotropic start "
            "given by the database, not a measured shear point" % first_row[3],
        ]
        if fnum(h.get("Dr_0_pct_database", "100")) < 50:
            caveats.append("loose specimen used as a SUBSTITUTE for the Fukushima & Tatsuoka "
                           "loose curves at 49-392 kPa, which do not exist in digital form: "
                           "other laboratory, density and preparation than the Tatsuoka-group "
                           "tests")
        if h.get("database_note"):
            caveats.append(h["database_note"])
        if h.get("peak_at_end_of_test") == "true":
            caveats.append("stress ratio still rising at the end of the test (peak_at_end_of_test)")
        if folder == "verdugo_ishihara_1996":
            # flag single-series flat ends (possible padding by the database)
            for j, name in ((1, "stress_ratio"), (3, "eps_v_pct")):
                lc = max([i for i in range(1, len(out)) if out[i][j] != out[i - 1][j]], default=0)
                if len(out) - 1 - lc >= 5:
                    caveats.append("%s is exactly constant (%s) from eps_a %s %% to the end (%d rows "
                                   "unchanged): possibly the database holding the last value "
                                   "(the padding seen in the Chen & Yang files) rather than a "
                                   "measured steady state; values kept, treat them as unverified"
                                   % (name, out[lc][j], out[lc][0], len(out) - 1 - lc))
        uncertainty = ("not stated by the database (values digitised from published figures; "
                       "strains to 4 decimals, stresses to 0.01 kPa)")
        source = "%s; via %s" % (paper, h["source"].split("; original data:")[0])
        database = CIT_WANG
        bedding, bedding_note = 0, BEDDING_WANG

    header = [
        ("id", tid),
        ("source", source),
        ("database", database),
        ("kind", kind + (" (triaxial compression)" if kind == "TC" else
                         " (plane-strain compression)")),
        ("drainage", "drained"),
        ("sigma3_kPa", h["sigma3_kPa"]),
        ("e0", h["e0"]),
        ("e0_definition", h["e0_definition"]),
        ("bedding_angle_deg", bedding),
        ("bedding_angle_note", bedding_note),
        ("strain_range_pct", "%s %s" % (fmt(strain_lo), fmt(strain_hi))),
        ("strain_range_note", "eps_a range of usable data: from the first real point (Wang "
                              "database files: from 0) to the last real point%s"
         % (" (PSC: to the peak)" if kind == "PSC" else
            " (after the cut)" if folder == "chen_yang_2025" else "")),
        ("stress_ratio_strain_range_pct", "%s %s" % (fmt(sr_lo), fmt(sr_hi))),
        ("eps_v_strain_range_pct", "%s %s" % (fmt(ev_lo), fmt(ev_hi))),
        ("uncertainty", uncertainty),
        ("caveats", " | ".join(caveats)),
        ("sign_convention", SIGN_CURVE),
        ("sign_check", sign_check),
        ("columns", COLUMNS_CURVE + (COLUMNS_PSC_EXTRA if extra else "")),
    ]
    if cut_info:
        header.append(("cut", "source rows %d, kept %d, cut %d (eps_a %s to %s %%, padded "
                              "repeats of the row at %s %%)"
                       % (cut_info[0], cut_info[1], cut_info[2], cut_info[4], cut_info[5],
                          fmt(cut_info[3]))))
    # remaining source keys, copied as they are
    for k, v in keys:
        if k not in CONSUMED:
            header.append((k, v))
    header.append(("source_file", "%s/%s (%d data rows)" % (folder, fname, n_src)))
    header.append(("converted_by", "data/lab/convert.py"))

    columns = ["eps_a_pct", "stress_ratio", "q_kPa", "eps_v_pct"] + extra
    dst = os.path.join(out_dir, folder, tid + ".csv")
    write_file(dst, header, columns, out)
    log.append({
        "file": os.path.relpath(dst, out_dir), "id": tid, "folder": folder, "kind": kind,
        "sigma3": h["sigma3_kPa"], "e0": h["e0"], "bedding": bedding,
        "range": "%s-%s" % (fmt(strain_lo), fmt(strain_hi)), "rows": len(out), "src_rows": n_src,
        "cut": cut_info, "src_path": path, "ev_min": ev_min, "ev_max": ev_max,
    })
    return dst


# --------------------------------------------------------------------------------------------
# Fukushima & Tatsuoka Table 1
# --------------------------------------------------------------------------------------------
def convert_ft84_table(src_dir, out_dir, log):
    path = os.path.join(src_dir, "fukushima_tatsuoka_1984", "table1_tests.csv")
    _, comments, cols, rows = read_commented_csv(path)
    meta_keys, _, mcols, mrows = read_commented_csv(
        os.path.join(src_dir, "fukushima_tatsuoka_1984", "curves_meta.csv"))
    curve_of = {r[mcols.index("table1_test")]: r[mcols.index("id")] for r in mrows}
    e_max, e_min = 0.977, 0.605
    out = []
    for r in rows:
        e = r[cols.index("e_0p3")]
        dr = fmt(100.0 * (e_max - fnum(e)) / (e_max - e_min), 1)
        out.append(r + [dr, curve_of.get(r[0], "")])
    header = [
        ("id", "ft84_table1"),
        ("source", CIT_FT84 + "; Table 1 (p. 32): 78 drained triaxial compression tests on "
                              "air-pluviated saturated Toyoura sand"),
        ("database", DB_THIRD_TABLE),
        ("kind", "TC (triaxial compression), peak values only"),
        ("drainage", "drained"),
        ("e0_definition", "e_0p3 = void ratio at sigma_c' = 0.3 kgf/cm2 = 29.4 kPa (for tests "
                          "sheared below 29.4 kPa ESTIMATED from the consolidation curve, p. 35); "
                          "the void ratio at the shearing stress is NOT reported"),
        ("bedding_angle_deg", 0),
        ("bedding_angle_note", BEDDING_FT84),
        ("uncertainty", "printed numbers transcribed by eye: none expected on the digits; "
                        "phi printed to 0.1 deg"),
        ("caveats", "phi_deg_uncorrected is from the MID-HEIGHT stress ratio, NOT corrected for "
                    "membrane forces (the paper's corrected values exist only as plotted points) | "
                    "sigma3_used_kPa is the measured (sigma3')_f where given, else the nominal "
                    "sigma_c' (tests 73-78 at 392 kPa) | loose tests (e.g. 50, 62, 71, 77: Dr about "
                    "38-40 %, 49-392 kPa) have peak values here but NO digitised stress-strain "
                    "curves | Dr_0p3_pct_derived uses e_max 0.977, e_min 0.605 and e_0p3, so it is "
                    "the density at 29.4 kPa, not at shearing"),
        ("columns", "test = Table 1 test number | sigma_c_kPa = nominal consolidation stress "
                    "(kgf/cm2 x 98) | sigma3_f_kPa = measured sigma3' at failure (empty: not "
                    "measured) | sigma3_used_kPa, sigma3_used_note = sigma3' to use with sr | "
                    "e_0p3 = void ratio at 29.4 kPa | t0_mm = membrane thickness | "
                    "phi_deg_uncorrected = peak friction angle [deg] | sr_derived = "
                    "(1+sin phi)/(1-sin phi) (derived by the transcriber) | Dr_0p3_pct_derived = "
                    "100 (0.977 - e_0p3)/(0.977 - 0.605) (derived here) | curve_id = the digitised "
                    "curve file of this test in this folder (empty: none)"),
        ("sign_convention", "compression positive (stresses)"),
        ("source_file", "fukushima_tatsuoka_1984/table1_tests.csv (%d data rows)" % len(rows)),
        ("converted_by", "data/lab/convert.py"),
    ]
    dst = os.path.join(out_dir, "fukushima_tatsuoka_1984", "table1_peak_friction.csv")
    write_file(dst, header, cols + ["Dr_0p3_pct_derived", "curve_id"], out)
    log.append({"file": os.path.relpath(dst, out_dir), "rows": len(out), "src_rows": len(rows),
                "src_path": path, "table": True})
    sc = [fnum(r[cols.index("sigma_c_kPa")]) for r in rows]
    ee = [r[cols.index("e_0p3")] for r in rows]
    T1_RANGE[0] = (len(rows), fmt(min(sc), 2), fmt(max(sc), 2),
                   min(ee, key=fnum), max(ee, key=fnum))


T1_RANGE = [None]


# --------------------------------------------------------------------------------------------
# Lam & Tatsuoka Fig. 21
# --------------------------------------------------------------------------------------------
def convert_lt88_tables(src_dir, out_dir, log):
    common_caveats = ("e_0.3 = 0.70 (looser than the digitised curves in this folder, e_0.3 "
                      "0.637-0.675), sigma3' = 98 kPa | xi = angle of the projection of the "
                      "deposition axis (paper Fig. 1): rows with xi_deg = 90 have the deposition "
                      "direction in the sigma1-sigma3 plane and are the ones for the project's "
                      "plane-strain convention, where omega_deg = bedding_angle_deg | "
                      "read from the figure")
    # (a)
    path = os.path.join(src_dir, "lam_tatsuoka_1988", "fig21a_phi_vs_orientation.csv")
    _, comments, cols, rows = read_commented_csv(path)
    header = [
        ("id", "lt88_fig21a_phi_vs_orientation"),
        ("source", CIT_LT88 + "; Fig. 21(a), p. 101"),
        ("database", DB_THIRD),
        ("kind", "peak friction angle of drained TC, PSC and TE tests against the orientation "
                 "of the bedding planes"),
        ("drainage", "drained"),
        ("sigma3_kPa", "98"),
        ("e0", "0.70"),
        ("e0_definition", "e_0.3 = void ratio at 29.4 kPa (the paper's density label); the void "
                          "ratio at shearing is not reported"),
        ("uncertainty", "phi +-0.25 deg (reading)"),
        ("caveats", common_caveats + " | TC/PSC: omega = angle of sigma1' from the deposition "
                    "axis; for TE the abscissa is theta (sin theta = sin omega sin xi): sectors 1-2 "
                    "theta = xi / omega, sector 3 theta = 0 (flat lines), so TE rows' omega/xi are "
                    "category positions | empty phi = marker hidden or not legible; missing "
                    "category rows were not legible | PSC-1 (Tatsuoka et al. 1986 data, omega "
                    "56-67 deg) not transcribed | TE double / TE single / TE no = the three TE series "
                    "as labelled by the transcriber after the paper's Fig. 16 (failure-mode "
                    "categories; see the paper for their definition; Fig. 21(b) uses TE single)"),
        ("columns", "series = test type and series label of the paper | category_k = index of "
                    "the abscissa category (0-9) | category_label = the category as printed | "
                    "omega_deg = angle between sigma1' and the deposition direction [deg] | "
                    "xi_deg = angle of the projection of the deposition axis [deg] | phi_deg = "
                    "peak friction angle [deg]"),
        ("source_file", "lam_tatsuoka_1988/fig21a_phi_vs_orientation.csv (%d data rows)" % len(rows)),
        ("converted_by", "data/lab/convert.py"),
    ]
    dst = os.path.join(out_dir, "lam_tatsuoka_1988", "phi_vs_orientation.csv")
    write_file(dst, header, cols, rows)
    log.append({"file": os.path.relpath(dst, out_dir), "rows": len(rows), "src_rows": len(rows),
                "src_path": path, "table": True})
    # (b)
    path = os.path.join(src_dir, "lam_tatsuoka_1988", "fig21b_phi_vs_b.csv")
    _, comments, cols, rows = read_commented_csv(path)
    # the source's series labels contain commas (quoted CSV); the project's reader splits on
    # plain commas, so ", " becomes "; " in the labels (no other change)
    rows = [[r[0].replace(", ", "; ")] + r[1:] for r in rows]
    header = [
        ("id", "lt88_fig21b_phi_vs_b"),
        ("source", CIT_LT88 + "; Fig. 21(b), p. 101"),
        ("database", DB_THIRD),
        ("kind", "peak friction angle against b = (sigma2' - sigma3')/(sigma1' - sigma3') "
                 "for TC (b = 0), PSC and TE (b = 1)"),
        ("drainage", "drained"),
        ("sigma3_kPa", "98"),
        ("e0", "0.70"),
        ("e0_definition", "e_0.3 = void ratio at 29.4 kPa (the paper's density label); the void "
                          "ratio at shearing is not reported"),
        ("uncertainty", "phi +-0.3 deg, b +-0.02 (PSC), +-0.01 (TC/TE) (reading)"),
        ("caveats", common_caveats + " | TE points are the SINGLE-intersection failure mode | "
                    "group A = xi 90 with omega varying (the project's plane-strain set), B = xi 0, "
                    "C = omega 90 with xi varying | b at PSC failure is measured (0.24-0.36), not "
                    "0.3 exactly | points at b = 0 and 1 of groups B and C coincide with group A "
                    "(same stress state) and are not repeated"),
        ("columns", "series = legend group (the source's ', ' written as '; ' so that "
                    "the file splits on commas without CSV quoting) | omega_deg [deg] | xi_deg [deg] | mode = TC / PSC / TE "
                    "(theta for TE) | b = intermediate principal stress parameter [-] | phi_deg = "
                    "peak friction angle [deg]"),
        ("source_file", "lam_tatsuoka_1988/fig21b_phi_vs_b.csv (%d data rows)" % len(rows)),
        ("converted_by", "data/lab/convert.py"),
    ]
    dst = os.path.join(out_dir, "lam_tatsuoka_1988", "phi_vs_b.csv")
    write_file(dst, header, cols, rows)
    log.append({"file": os.path.relpath(dst, out_dir), "rows": len(rows), "src_rows": len(rows),
                "src_path": path, "table": True})


# --------------------------------------------------------------------------------------------
# Kimura et al. 1985
# --------------------------------------------------------------------------------------------
def convert_kimura(src_dir, out_dir, log):
    mpath = os.path.join(src_dir, "kimura_1985", "tests_meta.csv")
    _, mcom, mcols, mrows = read_commented_csv(mpath)
    dpath = os.path.join(src_dir, "kimura_1985", "fig9_load_settlement.csv")
    _, dcom, dcols, drows = read_commented_csv(dpath)
    ci = {c: i for i, c in enumerate(dcols)}
    caveats_common = (
        "the paper gives NO void ratio, unit weight or footing roughness for this series: "
        "e_assumed = 0.977 - D_r (0.977 - 0.597) and gamma_derived = Gs 9.81/(1 + e) with Gs 2.64 "
        "are ASSUMPTIONS of the transcriber, not data | side-wall friction of the 0.1 m box "
        "may raise q by 5-15 % | below q = 150 kPa the curves overlap in the figure and the early "
        "slope is unreliable | the first row (0,0) is the assumed origin, not digitised | rows are "
        "in the order along the digitised curve (not re-sorted) | the same paper has V75.1, H76.5, V64.6 and H61.0 curves that are not in "
        "this data set")
    mi = {c: i for i, c in enumerate(mcols)}
    written = []
    for m in mrows:
        tid = m[mi["test_id"]]
        case = m[mi["case"]]
        trows = [r for r in drows if r[ci["test_id"]] == tid]
        if str(len(trows)) != m[mi["n_points"]]:
            raise SystemExit("Kimura %s: %d rows vs n_points %s" % (tid, len(trows),
                                                                   m[mi["n_points"]]))
        extra = ""
        sb = [fnum(r[ci["s_over_B"]]) for r in trows]
        back = [sb[i - 1] - sb[i] for i in range(1, len(sb)) if sb[i] < sb[i - 1]]
        if back:
            extra += (" | on the steep post-peak branch S_over_B goes back %d times, by up to %s, "
                      "between neighbouring points (inside the reading uncertainty); not re-sorted"
                      % (len(back), fmt(max(back), 5)))
        if case == "H":
            extra += (" | H curves: up to q = 750 kPa H86.7 shares one ink band with H76.5 and "
                     "V64.6 in the figure, so its rising branch there is not separable "
                     "(+-0.002 S/B)")
        out = [[r[ci["s_over_B"]], r[ci["q_kPa"]], r[ci["s_proto_m"]]] for r in trows]
        header = [
            ("id", tid),
            ("source", CIT_K85 + "; Fig. 9 (p. 40), anisotropy series"),
            ("database", DB_THIRD),
            ("kind", "centrifuge strip footing, load-settlement"),
            ("case", "%s = load %s the bedding planes" % (case, "normal to (perpendicular)"
                                                         if case == "V" else "parallel to")),
            ("bedding_angle_deg", 0 if case == "V" else 90),
            ("bedding_angle_note", "angle between the load (vertical) and the deposition "
                                   "direction: V case (load perpendicular to the bedding "
                                   "plane) 0, H case (load parallel to it) 90 (paper p. 39, "
                                   "Fig. 8)"),
            ("sand", "dry Toyoura sand, pouring method"),
            ("D_r_pct", m[mi["D_r_pct"]]),
            ("e_assumed", m[mi["e_assumed"]] + " (ASSUMPTION, see caveats)"),
            ("gamma_derived_kN_m3", m[mi["gamma_derived_kN_m3"]] + " (ASSUMPTION, derived from "
                                                                   "e_assumed)"),
            ("B_model_mm", m[mi["B_model_mm"]]),
            ("g_level", m[mi["g_level"]]),
            ("B_prototype_m", m[mi["B_prototype_m"]]),
            ("q_peak_kPa", m[mi["q_peak_kPa"]]),
            ("S_over_B_at_peak", m[mi["s_over_B_at_peak"]]),
            ("uncertainty", "reading +-0.0007 S/B and +-5 kPa on isolated curve segments; up to "
                            "+-0.002 S/B where curves overlap; drafting accuracy of the original "
                            "figure not included"),
            ("caveats", caveats_common + extra),
            ("sign_convention", "settlement S positive downward (into the ground); q positive "
                                "compressive bearing pressure"),
            ("columns", "S_over_B = settlement / footing breadth [-] | q_kPa = mean bearing "
                        "pressure [kPa] (same in model and prototype) | S_prototype_m = "
                        "prototype settlement [m] = S_model_mm x 30 / 1000"),
            ("source_file", "kimura_1985/fig9_load_settlement.csv (%d rows of %s)"
             % (len(trows), tid)),
            ("converted_by", "data/lab/convert.py"),
        ]
        dst = os.path.join(out_dir, "kimura_1985", tid + ".csv")
        write_file(dst, header, ["S_over_B", "q_kPa", "S_prototype_m"], out)
        written.append(tid)
        log.append({"file": os.path.relpath(dst, out_dir), "rows": len(out),
                    "src_rows": len(trows), "src_path": dpath, "kimura": tid,
                    "q_peak": m[mi["q_peak_kPa"]], "D_r": m[mi["D_r_pct"]], "case": case})
    # tests_meta in the project's form
    ren = {"s_over_B_at_peak": "S_over_B_at_peak", "s_over_B_max": "S_over_B_max"}
    header = [
        ("id", "kimura_1985_tests_meta"),
        ("source", CIT_K85 + "; Fig. 9 (p. 40), anisotropy series, strip footing B = 30 mm at "
                             "30 g (prototype B = 0.90 m), dry Toyoura sand, pouring method"),
        ("database", DB_THIRD),
        ("caveats", caveats_common),
        ("columns", "test_id = case + D_r | case = V (load normal to bedding) / H (parallel) | "
                    "D_r_pct = relative density from the curve label | e_assumed, "
                    "gamma_derived_kN_m3 = ASSUMPTIONS (e_max 0.977, e_min 0.597, Gs 2.64) | "
                    "B_model_mm, g_level, B_prototype_m | n_points = rows of the curve file | "
                    "q_peak_kPa, S_over_B_at_peak, S_model_mm_at_peak, S_over_B_max = read from "
                    "the digitised curve"),
        ("source_file", "kimura_1985/tests_meta.csv (%d data rows)" % len(mrows)),
        ("converted_by", "data/lab/convert.py"),
    ]
    dst = os.path.join(out_dir, "kimura_1985", "tests_meta.csv")
    write_file(dst, header, [ren.get(c, c) for c in mcols], mrows)
    log.append({"file": os.path.relpath(dst, out_dir), "rows": len(mrows),
                "src_rows": len(mrows), "src_path": mpath, "table": True})


# --------------------------------------------------------------------------------------------
# read-back check
# --------------------------------------------------------------------------------------------
def check_curve(entry, out_dir):
    check_plain(os.path.join(out_dir, entry["file"]))
    keys, _, cols, rows = read_commented_csv(os.path.join(out_dir, entry["file"]))
    h = dict(keys)
    for k in ("id", "source", "database", "kind", "drainage", "sigma3_kPa", "e0", "e0_definition",
              "bedding_angle_deg", "uncertainty", "caveats", "sign_convention", "columns",
              "strain_range_pct"):
        assert h.get(k), "%s: missing key %s" % (entry["file"], k)
    assert cols[:4] == ["eps_a_pct", "stress_ratio", "q_kPa", "eps_v_pct"], cols
    skeys, _, scols, srows = read_commented_csv(entry["src_path"])
    assert len(srows) == entry["src_rows"]
    n_keep = entry["cut"][1] if entry["cut"] else len(srows)
    assert len(rows) == n_keep, (entry["file"], len(rows), n_keep)
    # verbatim values (source rows in order; output sorted stably; sources are sorted)
    s3 = fnum(h["sigma3_kPa"])
    for s, o in zip(srows[:n_keep], rows):
        s = s + [""] * (len(scols) - len(s))
        assert fnum(s[0]) == fnum(o[0]) and s[1] == o[1], (entry["file"], s, o)
        assert (s[2] == "") == (o[3] == ""), (entry["file"], s, o)
        if s[2] != "":
            assert fnum(s[2]) == fnum(o[3])
        for a, b in zip(s[3:], o[4:]):
            assert (a == "") == (b == "")
        if o[1] == "":
            assert o[2] == ""
        else:
            assert abs(fnum(o[2]) - (fnum(o[1]) - 1) * s3) < 1e-3
    # sorted, no all-empty data rows
    e = [fnum(r[0]) for r in rows]
    assert all(e[i] <= e[i + 1] for i in range(len(e) - 1))
    for r in rows:
        assert any(c != "" for c in r[1:]), (entry["file"], r)
    if entry["cut"]:
        # no flat tail left: the last row differs from the one before
        assert rows[-1][1:] != rows[-2][1:]
        assert abs(e[-1] - entry["cut"][3]) < 1e-9
    return len(rows)


def check_plain(path):
    """Every output file must split on plain commas (no CSV quoting): the project's C++ reader
    (driver/src/lab_data.cpp) does not handle quotes."""
    with open(path) as fh:
        for line in fh:
            if not line.startswith("#") and '"' in line:
                raise SystemExit("%s: quoted CSV cell: %s" % (path, line.strip()))


def check_table(entry, out_dir):
    check_plain(os.path.join(out_dir, entry["file"]))
    keys, _, cols, rows = read_commented_csv(os.path.join(out_dir, entry["file"]))
    assert len(rows) == entry["rows"] == entry["src_rows"], entry
    assert dict(keys).get("source") and dict(keys).get("caveats")
    if entry.get("kimura"):
        _, _, scols, srows = read_commented_csv(entry["src_path"])
        ci = {c: i for i, c in enumerate(scols)}
        srows = [r for r in srows if r[ci["test_id"]] == entry["kimura"]]
        for s, o in zip(srows, rows):
            assert [s[ci["s_over_B"]], s[ci["q_kPa"]], s[ci["s_proto_m"]]] == o
        assert max(fnum(r[1]) for r in rows) == fnum(entry["q_peak"])
    return len(rows)


# --------------------------------------------------------------------------------------------
# README
# --------------------------------------------------------------------------------------------
SHORT = {
    "ft84_fig5a_sc0p1": "dense; membrane bias at 9.8 kPa; sigma3' drift to 11.8 kPa; e_0.3 estimated",
    "ft84_fig5a_sc0p2": "dense; sigma3' drift to 20.9 kPa; e_0.3 estimated; only 5 eps_v points",
    "ft84_fig5a_sc0p5": "dense; e_0.3 not the void ratio at shearing; no data below ~0.8 %",
    "ft84_fig5a_sc1p0": "dense; e_0.3 not the void ratio at shearing; no data below ~1.2 %",
    "ft84_fig5a_sc2p0": "dense; e_0.3 not the void ratio at shearing; no data below ~0.7 %",
    "ft84_fig5a_sc4p0": "dense; e_0.3 not the void ratio at shearing; no data below ~0.7 %",
    "lt88_fig5a_w00_hw1p0": "eps_a converted from eps1-eps3; initial rise not resolved",
    "lt88_fig5a_w30_hw1p0": "eps_a converted from eps1-eps3; initial rise not resolved",
    "lt88_fig5a_w60_hw1p0": "eps_a converted from eps1-eps3; initial rise not resolved",
    "lt88_fig5a_w90_hw1p0": "eps_a converted from eps1-eps3; initial rise not resolved",
    "lt88_fig9_psc_w00_hw1p0": "PSC: to the peak only; eps_v band shared by both tests; +s2_over_s3",
    "lt88_fig9_psc_w00_hw1p9": "PSC: to the peak only; eps_v band shared by both tests; +s2_over_s3",
    "wang34_Tokyo_TMD4": "substitute (medium-loose); dilates at the end",
    "wang34_Tokyo_TMD5": "substitute (loose); stress ratio exactly constant from 19.9 %",
    "wang34_Tokyo_TMD6": "substitute (very loose, e0 > e_max); still rising at the end",
    "wang33_HKU_TMD1": "dense; padded tail cut at 3.3 %; peak not reached",
    "wang33_HKU_TMD3": "dense; padded tail cut at 3.3 %; peak not reached",
    "wang33_HKU_TMD5": "substitute (loose); padded tail cut at 9.9 %",
    "wang33_HKU_TMD6": "dense; padded tail cut at 4.4 %; peak just reached; eps_v start -0.0267 %",
    "wang33_HKU_TMD7": "substitute (loose); padded tail cut at 8.4 %",
}


def write_readme(log, out_dir):
    L = []
    a = L.append
    a("# Laboratory and centrifuge data on Toyoura sand (project format)")
    a("")
    a("Generated by `data/lab/convert.py` from the shared data set (`../shared/data` beside the "
      "repository, or the folder given as argument): `python3 data/lab/convert.py [SOURCE_DIR]`. "
      "Edit the script, not the files; it rewrites everything here, checks every file by reading "
      "it back, and rewrites this README.")
    a("")
    a("## Element-test curves: `<source_folder>/<id>.csv`")
    a("")
    a("Header lines `# key: value` (one line each), then one CSV table with a header row.")
    a("")
    a("| key | meaning |")
    a("|---|---|")
    for k, v in [
        ("id", "test id (= file name)"),
        ("source", "full citation of the paper and the figure/table"),
        ("database", "Wang database files: the database citation, DOI and licence CC-BY-4.0; "
                     "otherwise `" + DB_THIRD + "`"),
        ("kind", "`TC` triaxial compression or `PSC` plane-strain compression"),
        ("drainage", "`drained` (all tests)"),
        ("sigma3_kPa", "sigma3' held during shearing [kPa] (nominal for Fukushima & Tatsuoka; "
                       "the measured drift is in `sigma3_f_kPa`)"),
        ("e0, e0_definition", "void ratio and what it means, copied from the source. "
                              "Fukushima & Tatsuoka and Lam & Tatsuoka: e_0.3 at 29.4 kPa, NOT "
                              "at shearing; Wang database: at the start of shearing"),
        ("bedding_angle_deg, bedding_angle_note", "angle between sigma1' and the deposition "
                                                  "direction (0: load normal to the bedding "
                                                  "planes). Lam & Tatsuoka: their omega. "
                                                  "Others: 0 by ASSUMPTION (the note says why)"),
        ("strain_range_pct", "`lo hi`: eps_a range of usable data [%]: first to last real point "
                             "(Wang files from 0), PSC only to the peak, Chen & Yang only to the "
                             "cut"),
        ("stress_ratio_strain_range_pct, eps_v_strain_range_pct", "where each series has points"),
        ("uncertainty", "reading tolerance as stated by the source"),
        ("caveats", "all caveats that apply, separated by a vertical bar with spaces"),
        ("sign_convention, sign_check", "see below; `sign_check` records the eps_v extremes of "
                                        "the file"),
        ("columns", "column descriptions"),
        ("cut", "Chen & Yang only: rows removed"),
        ("source_file, converted_by", "provenance"),
    ]:
        a("| `%s` | %s |" % (k.replace(", ", "`, `"), v))
    a("")
    a("Further keys of the source headers (material, test, digitisation, phi_peak_deg, "
      "eps_peak_pct, x_conversion, omega_deg, xi_deg, H_over_W, ...) are copied unchanged after "
      "these.")
    a("")
    a("Columns: `eps_a_pct,stress_ratio,q_kPa,eps_v_pct` (PSC files add `s2_over_s3`):")
    a("")
    a("| column | unit | meaning |")
    a("|---|---|---|")
    a("| `eps_a_pct` | % | axial (major principal) strain, compression positive; rows sorted by it "
      "(ties keep the source order) |")
    a("| `stress_ratio` | - | sigma1'/sigma3' (source `sr`, copied verbatim) |")
    a("| `q_kPa` | kPa | (stress_ratio - 1) * sigma3_kPa = sigma1' - sigma3'; derived here. In PSC "
      "this is NOT the invariant q, since sigma2' != sigma3' |")
    a("| `eps_v_pct` | % | volumetric strain, contraction positive, dilation negative |")
    a("| `s2_over_s3` | - | PSC only: sigma2'/sigma3' (4 markers per test) |")
    a("")
    a("An EMPTY cell means no value at that strain (the two traces of the digitised figures were "
      "read at different strains); it is never zero. Interpolate each column on its own. The "
      "first row (eps_a 0, stress ratio 1) is the assumed isotropic start, not a measured point.")
    a("")
    curves = [e for e in log if not (e.get("table") or e.get("kimura"))]
    dil = [e for e in curves if e["ev_min"] < -0.5]
    con = [e for e in curves if e["ev_min"] >= -0.5]
    a("**Sign**: compression positive for stress and strain, as in `docs/conventions.md`. The "
      "source files give eps_v 'dilation negative', which is the same convention, so the values "
      "are kept as they are. Checked on the data: the dense specimens, and the medium-loose "
      "Verdugo & Ishihara TMD4 at 100 kPa (denser than critical), end with negative eps_v "
      "(dilation, down to %s %%): %s; the loose ones stay positive (contraction, up to %s %%): "
      "%s. See `sign_check` in each file."
      % (fmt(min(e["ev_min"] for e in dil)), ", ".join(e["id"] for e in dil),
         fmt(max(e["ev_max"] for e in con)), ", ".join(e["id"] for e in con)))
    a("")
    a("## Files")
    a("")
    a("| file | test | kind | sigma3 kPa | e0 | bedding deg | usable eps_a % | rows | caveat |")
    a("|---|---|---|---|---|---|---|---|---|")
    for e in log:
        if e.get("table") or e.get("kimura"):
            continue
        rows = "%d" % e["rows"]
        if e["cut"]:
            rows = "%d (of %d; %d cut)" % (e["rows"], e["cut"][0], e["cut"][2])
        a("| `%s` | %s | %s | %s | %s | %s | %s | %s | %s |"
          % (e["file"], e["id"], e["kind"], e["sigma3"], e["e0"], e["bedding"], e["range"], rows,
             SHORT.get(e["id"], "")))
    a("")
    a("e0: Fukushima & Tatsuoka and Lam & Tatsuoka give e_0.3 (void ratio at 29.4 kPa); Verdugo & "
      "Ishihara and Chen & Yang give e0 at the start of shearing.")
    a("")
    a("Tables and centrifuge data:")
    a("")
    a("| file | content | rows | caveat |")
    a("|---|---|---|---|")
    tdesc = {
        "fukushima_tatsuoka_1984/table1_peak_friction.csv":
            ("Fukushima & Tatsuoka Table 1: peak friction angle of %d drained TC tests, "
             "sigma_c' %s-%s kPa, e_0.3 %s-%s" % T1_RANGE[0], "phi uncorrected for membrane force; loose tests "
                                                "have no curves"),
        "lam_tatsuoka_1988/phi_vs_orientation.csv":
            ("Lam & Tatsuoka Fig. 21(a): phi vs omega/xi for TC, PSC, TE (e_0.3 0.70, 98 kPa)",
             "use xi_deg = 90 rows for the project's plane strain; TE abscissa is theta"),
        "lam_tatsuoka_1988/phi_vs_b.csv":
            ("Lam & Tatsuoka Fig. 21(b): phi vs b (e_0.3 0.70, 98 kPa)",
             "group A (xi 90) is the project's set; TE single-intersection mode"),
        "kimura_1985/tests_meta.csv":
            ("Kimura et al. test list: D_r, assumed e and gamma, B, g, peak",
             "e_assumed / gamma_derived are assumptions"),
    }
    for e in log:
        if e.get("kimura"):
            a("| `%s` | Kimura et al. Fig. 9, strip footing B 30 mm at 30 g (B 0.9 m), %s case, "
              "D_r %s %%, q_peak %s kPa; columns S_over_B,q_kPa,S_prototype_m | %d | e and gamma "
              "assumed; side-wall friction +5-15 %%; q < 150 kPa unreliable |"
              % (e["file"], e["case"], e["D_r"], e["q_peak"], e["rows"]))
        elif e.get("table"):
            d = tdesc.get(e["file"], ("", ""))
            a("| `%s` | %s | %d | %s |" % (e["file"], d[0], e["rows"], d[1]))
    a("")
    a("## What was cut")
    a("")
    a("Chen & Yang (2025) files from the Wang database are padded: after the last real point the "
      "values repeat unchanged to 12 %. The script finds the last row whose values differ from "
      "the row before, checks that every later row repeats it exactly and that this strain is "
      "the one stated in the source README, and cuts the rest:")
    a("")
    for e in log:
        if e.get("cut"):
            c = e["cut"]
            a("- `%s`: kept %d of %d rows, last real point at %s %%, cut %d rows (%s to %s %%)."
              % (e["id"], c[1], c[0], fmt(c[3]), c[2], c[4], c[5]))
    a("")
    a("Inside the kept part one series can already be flat: Chen & Yang TMD5 stress ratio from "
      "9.7 %, TMD6 stress ratio from 4.3 %, TMD7 eps_v from 8.3 % (1-2 rows each); kept and named "
      "in the caveats. Verdugo & Ishihara TMD5 has the stress ratio exactly constant (3.1695) from "
      "19.9 % to 29.8 % while eps_v still changes: possibly the same database padding of one "
      "series; kept, flagged in the file. Nothing else was removed; the only other change to "
      "source values is `-0` written as `0`.")
    a("")
    a("## Gaps (stated plainly)")
    a("")
    a("- No digital copy exists of the Fukushima & Tatsuoka (1984) LOOSE stress-strain curves at "
      "49-392 kPa (Table 1 has only their peak friction angles, e.g. tests 50, 62, 71, 77 at Dr "
      "about 38-40 %). The loose Verdugo & Ishihara (1996) tests (100 kPa, e0 0.831-0.996) and the "
      "loose Chen & Yang (2025) tests TMD5 and TMD7 (200 and 400 kPa, e0 0.83) are SUBSTITUTES "
      "from other laboratories, densities and preparation, not the same series.")
    a("- No digital copy exists of the Oda et al. (1978) plane-strain curves; the Lam & Tatsuoka "
      "(1988) PSC curves (omega 0 only, usable to the peak only) and the Fig. 21 tables are the "
      "plane-strain and bedding-orientation data.")
    a("- Small-strain stiffness cannot be fitted from the Fukushima & Tatsuoka and Lam & Tatsuoka "
      "curves (the initial rise was not digitised / not resolved).")
    a("- Kimura et al. (1985): only V85.6 and H86.7 are digitised; the paper gives no void ratio "
      "or unit weight for them.")
    a("- Chen & Yang (2025): the dense tests TMD1/3/6 end at 3.3-4.4 % axial strain with the "
      "stress ratio still rising (TMD1, TMD3) or just flat (TMD6): no peak or softening data; the "
      "full title and authors of the paper and the author list of the Wang database "
      "are not in the source files and have to be completed from the publications.")
    a("")
    a("## Citations and licence")
    a("")
    for c in (CIT_FT84, CIT_LT88, CIT_VI96, CIT_CY25, CIT_K85, CIT_WANG):
        a("- " + c + ".")
    a("")
    a("Licence note: the Fukushima & Tatsuoka, Lam & Tatsuoka and Kimura et al. numbers were "
      "digitised by a third party from figures and tables in Soils and Foundations and "
      "Geotechnique; they are fit for research calibration and validation with citation of the "
      "paper, not an open-data licence. The Verdugo & Ishihara and Chen & Yang curves come from "
      "the Wang sand triaxial database (4TU.ResearchData, doi "
      "10.4121/086847a6-ba39-4d66-973b-6b93028c7ad8) under CC-BY-4.0: cite the database and the "
      "paper. Cite the original paper whenever a result uses these data.")
    a("")
    with open(os.path.join(out_dir, "README.md"), "w") as fh:
        fh.write("\n".join(L))


# --------------------------------------------------------------------------------------------
def main(argv):
    src_dir = os.path.abspath(argv[1]) if len(argv) > 1 else DEFAULT_SRC
    out_dir = HERE
    if not os.path.isfile(os.path.join(src_dir, "README.md")):
        raise SystemExit("source folder not found: %s" % src_dir)
    log = []
    for folder in CURVE_FOLDERS:
        names = sorted(f for f in os.listdir(os.path.join(src_dir, folder))
                       if f.endswith(".csv") and not f.startswith(("curves_meta", "table1",
                                                                   "fig21")))
        for f in names:
            convert_curve(folder, f, src_dir, out_dir, log)
    convert_ft84_table(src_dir, out_dir, log)
    convert_lt88_tables(src_dir, out_dir, log)
    convert_kimura(src_dir, out_dir, log)
    write_readme(log, out_dir)
    # read back
    for e in log:
        n = check_table(e, out_dir) if (e.get("table") or e.get("kimura")) else check_curve(e, out_dir)
        extra = ""
        if e.get("cut"):
            c = e["cut"]
            extra = "  (source %d, cut %d padded rows %s-%s %%, last real point %s %%)" % (
                c[0], c[2], c[4], c[5], fmt(c[3]))
        print("%-52s %4d rows%s" % (e["file"], n, extra))
    print("all %d files checked" % len(log))


if __name__ == "__main__":
    main(sys.argv)
