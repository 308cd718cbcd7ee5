#!/usr/bin/env python3
"""Makes the expected values of test/unit/test_fn_internal.ml from POV-Ray 3.7.

Writes test/unit/data/fn_internal.pov (calls of every internal function of functions.inc at
several points and parameter sets), runs POV-Ray on it, and writes
test/unit/test_fn_internal_data.ml from what it prints. Each value is printed as a mantissa
(20 decimals, in [1, 2) or near) and a power of two, so that tiny and huge values keep all
their bits; the value is mantissa * 2^exponent exactly.

Run: python3 test/unit/data/fn_internal_gen.py  (from anywhere; needs povray, /usr/share/povray-3.7/include/functions.inc, and POV-Ray's
source/backend/vm/fnintern.cpp at /work/povsrc for the trap table.)
"""
import os, re, subprocess, sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
POV = os.path.join(ROOT, "test/unit/data/fn_internal.pov")
ML = os.path.join(ROOT, "test/unit/test_fn_internal_data.ml")
INC = "/usr/share/povray-3.7/include/functions.inc"
FNINTERN = "/work/povsrc/source/backend/vm/fnintern.cpp"

# points every function is called at: near the origin, on the y axis (x = z = 0), negative
# coordinates, far away
POINTS = [
    (0.3, 0.4, 0.5), (-0.7, 0.2, -0.35), (1.5, -2.25, 0.75), (0.0, 0.0, 0.0), (0.0, 1.3, 0.0),
    (0.001, -0.002, 0.0005), (-2.5, 3.1, -1.7), (0.9, -0.05, 1.2), (0.05, 0.6, -0.1),
    (-0.02, -0.8, 0.1),
]

# parameter sets of each function (the parameters after x, y, z), chosen to reach every branch
def sor_sets(base):
    # SOR switch 0 (off), 1 with angle 0, 1 with 30 degrees and offset, -1 (off again)
    return [base + (0.0, 0.0, 0.0), base + (1.0, 0.5, 0.0), base + (1.0, 0.3, 30.0), base + (-1.0, 0.2, 45.0)]
FIELD = [(1.0,), (0.25,), (50.0,), (-3.0,)]  # a field strength; 50 reaches the clamp at +-10

SETS = {
    "f_algbr_cyl1": [(1.0, 5.0) + r for r in [(0.0, 0.0, 0.0), (1.0, 0.5, 0.0), (1.0, 0.3, 30.0), (-1.0, 0.2, 45.0)]] + [(20.0, 0.5, 1.0, -0.4, -60.0)],
    "f_algbr_cyl2": [(1.0, 5.0) + r for r in [(0.0, 0.0, 0.0), (1.0, 0.5, 0.0), (1.0, 0.3, 30.0), (-1.0, 0.2, 45.0)]] + [(20.0, 0.5, 1.0, -0.4, -60.0)],
    "f_algbr_cyl3": [(1.0, 5.0) + r for r in [(0.0, 0.0, 0.0), (1.0, 0.5, 0.0), (1.0, 0.3, 30.0), (-1.0, 0.2, 45.0)]] + [(20.0, 0.5, 1.0, -0.4, -60.0)],
    "f_algbr_cyl4": [(1.0, 5.0) + r for r in [(0.0, 0.0, 0.0), (1.0, 0.5, 0.0), (1.0, 0.3, 30.0), (-1.0, 0.2, 45.0)]] + [(20.0, 0.5, 1.0, -0.4, -60.0)],
    "f_bicorn": [(1.0, 1.0), (0.5, 2.5), (80.0, 1.0), (-2.0, -0.5)],
    "f_bifolia": [(1.0, 3.0), (0.5, 1.0), (90.0, 3.0), (-2.0, -1.5)],
    "f_blob": [(1.0, 1.0, 1.0, 1.0, 1.0), (0.5, 2.0, 0.7, 1.5, 2.0), (2.0, -1.0, 3.0, 0.5, 0.25)],
    "f_blob2": [(1.0, 1.0, 1.0, 0.5), (0.5, 2.0, 3.0, -1.0), (-1.5, 0.25, 1.0, 0.0)],
    "f_boy_surface": [(1.0, 1.0), (0.01, 2.0), (50.0, 1.0), (-3.0, 0.5)],
    "f_comma": [(1.0,), (0.4,), (-2.0,)],
    "f_cross_ellipsoids": [(0.1, 1.0, 1.0, 0.5), (3.0, 0.5, 2.0, -0.25), (0.0, 2.0, 1.5, 1.0)],
    "f_crossed_trough": FIELD,
    "f_cubic_saddle": FIELD,
    "f_cushion": FIELD,
    "f_devils_curve": FIELD,
    "f_devils_curve_2d": sor_sets((1.0, 0.6, 0.5)) + [(40.0, 2.0, -1.0, 1.0, 0.0, -30.0)],
    "f_dupin_cyclid": [(1.0, 4.0, 2.0, 2.0, 0.5, 3.0), (0.5, 1.0, 0.5, -1.0, 2.0, 1.5), (20.0, 4.0, 2.0, 2.0, 0.5, 3.0), (1.0, 0.0, 0.0, 0.0, 0.0, 0.0)],
    "f_ellipsoid": [(1.0, 1.0, 1.0), (0.5, 2.0, 3.0), (-1.5, 0.0, 0.25)],
    "f_enneper": FIELD,
    "f_flange_cover": [(0.1, 1.0, 1.0, 0.5), (1.0, 0.5, 2.0, -0.25), (0.03, 2.0, 30.0, 1.0)],
    "f_folium_surface": [(1.0, 1.0, 1.0), (0.5, -0.5, 2.0), (60.0, 1.0, 1.0), (-2.0, 3.0, -1.0)],
    "f_folium_surface_2d": sor_sets((1.0, 1.0, 1.0)) + [(60.0, -0.5, 2.0, 1.0, -0.5, 90.0)],
    "f_glob": FIELD,
    "f_heart": FIELD,
    "f_helical_torus": [(1.0, 8.0, 1.0, 0.3, 0.5, 0.2, 1.0, 2.0, 0.1, 0.0),
                        (0.8, 3.0, -2.0, 0.5, 0.0, 0.4, 0.5, 5.0, 2.0, 1.5),
                        (2.0, -5.0, 0.5, 1.0, 1.0, -0.3, 2.0, 1.0, -0.5, 0.25)],
    "f_helix1": [(2.0, 1.0, 0.1, 0.5, 1.0, 1.0, 0.0), (1.0, 2.0, 0.2, 1.0, 0.5, 2.0, 0.0),
                 (3.0, 0.5, 0.15, 0.8, 2.0, 0.5, 45.0), (2.0, -1.5, 0.1, 0.5, 1.0, 0.0, 30.0),
                 (1.0, 1.0, 0.3, 0.6, 1.5, 0.0, 0.0), (2.0, 1.0, 0.1, 0.5, 1.0, 1.0, 20.0)],
    "f_helix2": [(0.0, 2.0, 0.3, 0.5, 0.0, 1.0, 0.0), (0.0, 1.0, 0.2, 1.0, 0.0, 2.0, 0.0),
                 (0.0, -3.0, 0.15, 0.8, 0.0, 0.5, 45.0), (0.0, 1.5, 0.1, 0.5, 0.0, 0.0, 30.0)],
    "f_hex_x": [(0.0,), (1.0,)],
    "f_hex_y": [(0.0,), (1.0,)],
    "f_hetero_mf": [(0.5, 2.0, 6.0, 0.5, 1.0, 2.0), (0.8, 2.5, 4.5, 0.0, 0.0, 1.0),
                    (0.3, 1.7, 3.25, 0.25, 2.0, 3.0), (1.0, 2.0, 1.0, 0.5, 1.0, 0.0),
                    (0.5, 2.0, 0.5, 1.0, 3.0, 5.0), (0.2, 3.0, 5.0, -0.3, 1.7, -1.0)],
    "f_hunt_surface": FIELD + [(0.001,)],
    "f_hyperbolic_torus": [(1.0, 1.0, 0.5), (0.5, 2.0, 1.0), (30.0, 1.0, 0.5), (-1.0, 0.0, 2.0)],
    "f_isect_ellipsoids": [(0.1, 1.0, 1.0, 0.5), (3.0, 0.5, 2.0, -0.25), (0.0, 2.0, 1.5, 1.0)],
    "f_kampyle_of_eudoxus": [(1.0, 0.0, 1.0), (0.5, 1.0, 2.0), (50.0, 0.5, 1.0), (-2.0, -1.0, 0.5)],
    "f_kampyle_of_eudoxus_2d": sor_sets((1.0, 0.0, 1.0)) + [(50.0, 0.5, 2.0, 1.0, 0.7, 10.0)],
    "f_klein_bottle": FIELD,
    "f_kummer_surface_v1": FIELD,
    "f_kummer_surface_v2": [(1.0, -0.95, 0.0, 0.0), (0.5, -0.5, -1.0, 2.0), (40.0, -1.2, -0.5, -3.0), (-1.0, 0.3, 1.0, 1.0)],
    "f_lemniscate_of_gerono": FIELD,
    "f_lemniscate_of_gerono_2d": sor_sets((1.0, 1.0, 1.0)) + [(50.0, 2.0, 0.5, 1.0, 0.0, -45.0)],
    "f_mesh1": [(1.0, 1.0, 1.0, 0.5, 1.0), (0.4, 0.7, 2.0, 0.1, 3.0), (2.0, 0.5, 0.5, 0.0, 1.0)],
    "f_mitre": FIELD,
    "f_nodal_cubic": FIELD,
    "f_odd": FIELD,
    "f_ovals_of_cassini": [(1.0, 0.5, 0.25, 4.0), (0.5, 1.0, 0.0, 2.0), (60.0, 0.5, 0.25, 4.0), (-1.0, 2.0, 1.0, -1.0)],
    "f_paraboloid": FIELD,
    "f_parabolic_torus": [(1.0, 1.0, 0.5), (0.5, 2.0, 1.0), (30.0, 1.0, 0.5), (-1.0, 0.0, 2.0)],
    "f_ph": [()],
    "f_pillow": FIELD,
    "f_piriform": FIELD,
    "f_piriform_2d": [(1.0, 1.0, -1.0, 0.5, 0.0, 0.0, 0.0), (1.0, 1.0, -1.0, 0.5, 1.0, 0.5, 0.0),
                      (0.5, 2.0, -0.5, 1.0, 1.0, 0.3, 30.0), (-1.0, 1.0, -1.0, 2.0, -1.0, 0.2, 45.0),
                      (60.0, 1.0, -1.0, 0.5, 1.0, -0.2, -20.0)],
    "f_poly4": [(0.0, 0.0, 1.0, 0.0, 0.0), (1.0, -2.0, 0.5, 0.25, -1.0), (-6.0, 0.0, 0.0, 0.0, 0.0), (0.5, 1.0, -3.0, 2.0, -4.0)],
    "f_polytubes": [(3.0, 0.5, 0.0, 0.0, 0.0, 0.0), (5.0, 0.2, 0.1, -0.3, 0.05, 0.02), (0.0, 1.0, 0.0, 0.0, 0.0, 0.0),
                    (2.7, 0.4, 1.0, 0.0, 0.0, 0.0), (1.0, -0.5, 0.0, 1.0, 0.0, 0.0)],
    "f_quantum": [(0.0,), (1.0,)],
    "f_quartic_paraboloid": FIELD,
    "f_quartic_saddle": FIELD,
    "f_quartic_cylinder": [(1.0, 0.5, 0.5), (0.5, 2.0, 1.0), (40.0, 1.0, 3.0), (-1.0, 0.0, 0.0)],
    "f_r": [()],
    "f_ridge": [(2.0, 6.0, 0.5, 0.5, 0.5, 2.0), (2.2, 4.5, 0.6, 0.2, 0.7, 1.0), (1.9, 1.0, 0.5, 0.8, 0.3, 3.0),
                (2.0, 3.75, 0.4, 0.0, 1.0, 0.0), (2.5, 0.5, 0.5, 1.5, -0.5, 6.0)],
    # the first call fixes the exponent array (H 0.7, lacunarity 2.1, 6.5 octaves: 7 entries);
    # the later ones keep it whatever their H and lacunarity, and stay within its 7 entries
    "f_ridged_mf": [(0.7, 2.1, 6.5, 1.0, 2.0, 2.0), (0.25, 2.0, 6.0, 0.9, 1.0, 1.0), (0.5, 1.8, 3.0, 1.2, 3.0, 3.0),
                    (0.9, 2.5, 1.0, 1.0, 2.0, 0.0), (0.1, 3.0, 0.5, 0.5, 0.5, 6.0),
                    (0.5, 2.0, 4.0, 1.0, -1.0, 2.0)],  # a negative gain: weights below 0 clip to 0
    "f_rounded_box": [(0.1, 1.0, 1.0, 1.0), (0.3, 0.5, 1.5, 0.25), (0.0, 1.0, 2.0, 0.5), (1.0, 0.2, 0.2, 0.2)],
    "f_sphere": [(1.0,), (0.25,), (-0.5,)],
    "f_spikes": [(0.05, 1.0, 1.0, 0.5, 2.0), (0.5, 2.0, 0.5, 1.0, 0.5), (1.0, 0.3, 2.0, 0.0, 1.0)],
    "f_spikes_2d": [(0.9, 12.0, 8.0, 1.0), (2.0, 3.0, -5.0, 0.1), (0.5, 0.0, 1.0, 3.0)],
    "f_spiral": [(0.3, 0.1, 1.0, 0.0, 0.0, 1.0), (0.5, 0.2, 2.0, 0.0, 0.0, 0.0), (0.4, 0.15, 3.0, 0.0, 0.0, 0.5),
                 (0.25, 0.05, 1.5, 0.0, 0.0, 2.0)],
    "f_steiners_roman": FIELD,
    "f_strophoid": [(1.0, 1.0, 0.0, 1.0), (0.5, -1.0, 0.5, 2.0), (50.0, 1.0, -0.5, 1.0), (-1.0, 2.0, 1.0, 0.5)],
    "f_strophoid_2d": [(1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0), (1.0, 1.0, 0.0, 1.0, 1.0, 0.5, 0.0),
                       (0.5, -1.0, 0.5, 2.0, 1.0, 0.3, 30.0), (-1.0, 2.0, 1.0, 0.5, -1.0, 0.2, 45.0),
                       (50.0, 1.0, -0.5, 1.0, 1.0, -0.3, 70.0)],
    "f_superellipsoid": [(1.0, 1.0), (0.25, 0.5), (2.0, 3.0), (0.5, 1.5)],
    "f_th": [()],
    "f_torus": [(1.0, 0.25), (0.5, 0.1), (2.0, 1.0)],
    "f_torus2": [(1.0, 1.0, 0.25), (0.5, 2.0, 1.0), (30.0, 1.0, 0.5), (-1.0, 0.0, 2.0)],
    "f_torus_gumdrop": FIELD,
    "f_umbrella": FIELD,
    "f_witch_of_agnesi": [(1.0, 0.04), (0.5, 1.0), (50.0, 0.5), (-1.0, -0.2)],
    "f_witch_of_agnesi_2d": sor_sets((1.0, 0.2, 0.5)) + [(50.0, 1.0, -1.0, 1.0, 0.5, -30.0)],
    "f_noise3d": [()],
    "f_noise_generator": [(0.0,), (1.0,), (2.0,), (3.0,), (4.0,), (-1.0,), (2.7,), (7.0,)],
}

# points some functions also need: f_hex_x/y at a hexagon's centre (x1 = y1 = 0) and at the
# 30-degree boundary; f_enneper with |z| < 0.2 of both signs; the noises at larger coordinates
EXTRA = {
    "f_hex_x": [(0.8660254037844386, 1.5, 0.0), (-3.0, 7.25, 1.0), (2.1, -4.4, 0.0), (0.4, 0.1, 0.0), (5.0, 0.0, 0.0)],
    "f_hex_y": [(0.8660254037844386, 1.5, 0.0), (-3.0, 7.25, 1.0), (2.1, -4.4, 0.0), (0.4, 0.1, 0.0), (5.0, 0.0, 0.0)],
    "f_enneper": [(0.5, 0.3, -0.1), (0.2, -0.4, 0.15), (1.0, 1.0, -0.25), (0.7, -0.2, 0.0)],
    "f_helical_torus": [(0.0, 0.5, 0.0), (-1.0, 0.0, -0.2), (0.2, -0.3, -1.1)],
    "f_mesh1": [(-3.7, 0.1, -2.2), (5.5, -0.3, 0.25)],
    "f_hetero_mf": [(12.5, -7.25, 3.125), (-100.5, 20.25, 0.75)],
    "f_ridge": [(12.5, -7.25, 3.125), (-100.5, 20.25, 0.75)],
    "f_ridged_mf": [(12.5, -7.25, 3.125), (-100.5, 20.25, 0.75)],
    "f_noise3d": [(12.5, -7.25, 3.125), (-100.5, 20.25, 0.75), (0.5, 0.5, 0.5)],
    "f_noise_generator": [(12.5, -7.25, 3.125), (-100.5, 20.25, 0.75)],
}

def trap_table():
    text = open(FNINTERN).read()
    table = text[text.index("POVFPU_TrapTable[] ="):text.index("POVFPU_TrapSTable[]")]
    rows = re.findall(r"\{\s*(f_\w+),\s*(\d+)\s*\+\s*3\s*\},\s*//\s*(\d+)", table)
    assert len(rows) == 79, len(rows)
    return [(int(k), name, int(n) + 3) for name, n, k in rows]

def include_names():
    names = {}
    for m in re.finditer(r"#declare\s+(f_\w+)\s*=\s*function\s*\{\s*internal\((\d+)\)\s*\}", open(INC).read()):
        names[int(m.group(2))] = m.group(1)
    return names

def fmt(v):
    return repr(float(v))

def pov_call(name, args):
    return "%s(%s)" % (name, ", ".join(fmt(a) for a in args))

def cases(table):
    out = []
    for k, name, arity in table:
        if name == "f_pattern":
            continue
        for s, params in enumerate(SETS[name]):
            assert len(params) + 3 == arity, (name, params)
            for i, p in enumerate(POINTS + EXTRA.get(name, [])):
                out.append((k, name, p + params))
    return out

def write_pov(calls):
    lines = [
        "// Generated by fn_internal_gen.py (which also turns POV-Ray's output into",
        "// test/unit/test_fn_internal_data.ml): every internal function of functions.inc at several",
        "// points and parameter sets. Each value is printed as a mantissa and a power of two",
        "// (Out below) so that no bit is lost. Run:",
        "//   povray +Ifn_internal.pov +O/tmp/fn.png +W8 +H8 -D +L/usr/share/povray-3.7/include",
        "#version 3.7;",
        "global_settings { assumed_gamma 1 }",
        '#include "functions.inc"',
        "// (V = 0 would not do: POV-Ray's = allows a difference of 1e-10; < and > are exact)",
        "#macro Out(Tag, V)",
        "  #if ((V < 0) | (V > 0))",
        "    #local E = floor(ln(abs(V)) / ln(2));",
        "    #local M = V * pow(2, -E);",
        '    #debug concat(Tag, " ", str(M, 0, 20), " ", str(E, 0, 0), "\\n")',
        "  #else",
        '    #debug concat(Tag, " 0 0\\n")',
        "  #end",
        "#end",
    ]
    for n, (k, name, args) in enumerate(calls):
        lines.append('Out("V %d", %s)' % (n, pov_call(name, args)))
    # f_noise3d with the scene's generator set to 1 and then 3 (global_settings takes effect
    # for the calls after it)
    for gen in (1, 3):
        lines.append("global_settings { noise_generator %d }" % gen)
        for n, p in enumerate(POINTS + EXTRA["f_noise3d"]):
            lines.append('Out("G %d %d", %s)' % (gen, n, pov_call("f_noise3d", p)))
    lines.append("camera { location -z look_at 0 }")
    open(POV, "w").write("\n".join(lines) + "\n")

def run_pov():
    env = dict(os.environ)
    if os.path.exists("/work/gen/empty.ini"):  # no user povray.ini switches
        env["POVINI"] = "/work/gen/empty.ini"
    r = subprocess.run(["povray", "+I" + POV, "+O/tmp/fn_internal.png", "+W8", "+H8", "-D", "-V",
                        "+L/usr/share/povray-3.7/include"], env=env, capture_output=True, text=True)
    values = {}
    gens = {}
    for line in r.stderr.splitlines():
        f = line.split()
        if len(f) == 4 and f[0] == "V":
            values[int(f[1])] = float(f[2]) * 2.0 ** int(f[3])
        elif len(f) == 5 and f[0] == "G":
            gens[(int(f[1]), int(f[2]))] = float(f[3]) * 2.0 ** int(f[4])
    return values, gens

def write_ml(table, names, calls, values, gens):
    o = []
    o.append("(* Generated by test/unit/data/fn_internal_gen.py from POV-Ray 3.7.0.10's output for")
    o.append("   test/unit/data/fn_internal.pov; do not edit. *)")
    o.append("")
    o.append("(* internal(k): POVFPU_TrapTable's parameter count (fnintern.cpp) and functions.inc's name,")
    o.append("   \"\" where functions.inc declares none *)")
    o.append("let table = [|")
    for k, name, arity in table:
        o.append('  (%d, %d, "%s");' % (k, arity, names.get(k, "")))
    o.append("|]")
    o.append("")
    o.append("(* internal(k), its arguments (x, y, z, then the parameters), the value POV-Ray printed; in the")
    o.append("   order the scene calls them (f_ridged_mf keeps state from its first call) *)")
    o.append("let calls = [|")
    for n, (k, name, args) in enumerate(calls):
        o.append("  (%d, [| %s |], %s);" % (k, "; ".join(fmt(a) for a in args), fmt(values[n])))
    o.append("|]")
    o.append("")
    o.append("(* f_noise3d with the scene's noise_generator: generator, point, value *)")
    o.append("let noise3d = [|")
    for (gen, n), v in sorted(gens.items()):
        p = (POINTS + EXTRA["f_noise3d"])[n]
        o.append("  (%d, [| %s |], %s);" % (gen, "; ".join(fmt(a) for a in p), fmt(v)))
    o.append("|]")
    open(ML, "w").write("\n".join(o) + "\n")

def main():
    table = trap_table()
    names = include_names()
    calls = cases(table)
    write_pov(calls)
    values, gens = run_pov()
    missing = [n for n in range(len(calls)) if n not in values]
    if missing:
        sys.exit("POV-Ray printed no value for calls %s" % missing[:10])
    write_ml(table, names, calls, values, gens)
    print("%d calls, %d noise3d values" % (len(calls), len(gens)))

main()
