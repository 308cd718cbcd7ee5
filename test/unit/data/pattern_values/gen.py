#!/usr/bin/env python3
"""POV-Ray's pattern values for test/unit/test_pattern_values.ml.

Writes the scenes beside this file, runs the installed povray on them, and writes
test/unit/test_pattern_values_data.ml with every value it printed.

Two routes to a value at full double precision:

* "pattern": a function { pattern { P frequency 0 ramp_wave } } returns Evaluate_TPat's value
  unwrapped (a negative value v becomes v - floor v), printed with str(v, 0, 20): 20 decimals,
  which identify the double.
* "pigment", for the patterns the pattern function cannot parse (pavement, tiling, the fractal
  exterior types 7 and 8): function { pigment { P color_map { [0 rgb 0] [1 rgb 1] } frequency F } }
  gives red = f32(fmod(v F, 1.00001)), exact for F a power of two. Three runs: F = 1 gives v to
  24 bits, F = 2^(16-e) and then 2^(30-e) (v in [2^e, 2^(e+1))) give the multiple of 1.00001 from
  the run before and 24 more bits of the remainder, so that v is known to an eighth of its ulp.
* "list" for square and triangular (integer values): pigment { P rgb 0, rgb 1, ... }.

Run from the repository root:  python3 test/unit/data/pattern_values/gen.py
"""
import math, os, random, subprocess, sys
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, '..', '..', '..', '..'))
OUT_ML = os.path.join(ROOT, 'test', 'unit', 'test_pattern_values_data.ml')

G3 = [(0.3, 0.4, 1.7), (-1.2, 0.75, 0.35), (2.6, -0.8, -3.1), (-0.45, -1.9, -0.7),
      (5.13, 2.2, 0.91), (0.07, 0.11, -0.23), (-3.7, 4.4, 2.9), (1.01, -0.33, -6.25)]
FRAC = [(0.3, 0.4, 0.0), (-0.75, 0.1, 0.0), (-1.2, 0.35, 0.0), (0.1, 0.62, 0.0), (-0.5, -0.5, 0.0),
        (0.28, 0.01, 0.0), (-1.9, 0.0, 0.0), (0.45, -0.3, 0.0), (-0.2, 0.1, 0.0), (-1.0, 0.05, 0.0),
        (0.2, -0.1, 0.0), (-0.1, -0.7, 0.0)]
MAGNET = [(0.5, 0.5, 0.0), (1.2, -0.3, 0.0), (2.5, 0.8, 0.0), (-0.5, 1.1, 0.0), (1.9, 0.05, 0.0),
          (0.0, 0.0, 0.0), (3.1, -1.2, 0.0), (1.05, 1.5, 0.0), (1.4, 0.2, 0.0), (0.9, -0.9, 0.0)]
rng = random.Random(37)
XZ = [(round(rng.uniform(-7, 7), 3), 0.37, round(rng.uniform(-7, 7), 3)) for _ in range(40)]
XZ24 = XZ[:24]
XZ200 = XZ + [(round(rng.uniform(-12, 12), 3), -1.5, round(rng.uniform(-12, 12), 3)) for _ in range(160)]
NEAR_AXIS = G3 + [(0.0005, 1.0, 0.0002), (0.0, -2.0, 0.0), (-0.0009, 0.5, -0.3)]
G3_XZ24 = G3 + XZ24
CUBIC = G3 + [(1, 1, 1), (-1, 0.5, -1), (0.2, -3, 0.1), (0, 0, -2)]
G3_MORE = G3 + [(0.1, 0.2, 0.3), (0.5, -0.7, 0.2)]
G3_PLANAR = G3 + [(0.1, 0.2, 0.3), (0, -0.7, 0)]
G3_QUILT = G3 + [(-2.0, 3.0, -1.0)]
G3_AXIS = G3 + [(0, 0, 1.5)]
G3_CELLS = G3 + [(-0.00000000005, 1.0, 2.99999999995)]
CR = G3 + [(10.5, -20.25, 30.125), (-0.5, -0.5, -0.5), (0.99999, 1e-11, -1e-11), (123.4, 56.7, -89.1)]
POINT_SETS = [('g3', G3), ('frac', FRAC), ('magnet', MAGNET), ('xz', XZ), ('xz24', XZ24), ('xz200', XZ200),
              ('near_axis', NEAR_AXIS), ('g3_xz24', G3_XZ24), ('cubic', CUBIC), ('g3_more', G3_MORE),
              ('g3_planar', G3_PLANAR), ('g3_quilt', G3_QUILT), ('g3_axis', G3_AXIS), ('g3_cells', G3_CELLS),
              ('crackle', CR)]


def set_name(points):
    for name, s in POINT_SETS:
        if s is points:
            return name
    raise ValueError('not a named point set')


def ml_float(x):
    s = repr(float(x))
    if 'inf' in s or 'nan' in s:
        raise ValueError(s)
    if '.' not in s and 'e' not in s:
        s += '.'
    return '(' + s + ')' if s.startswith('-') else s


cases = []


def case(label, pov, ml, points, route='pattern', suite='plain', warps='[]', gen=2, freq=None, phase=None, ramp=False):
    cases.append(dict(label=label, pov=pov, ml=ml, points=points, route=route, suite=suite, warps=warps,
                      gen=gen, freq=freq, phase=phase, ramp=ramp))


def f32(x):
    return 'f32 ' + ml_float(x)


# -- patterns without noise ---------------------------------------------------------------------
case('square', 'square rgb 0, rgb 1, rgb 2, rgb 3', 'Square', G3_XZ24, route='list')
case('triangular', 'triangular rgb 0, rgb 1, rgb 2, rgb 3, rgb 4, rgb 5', 'Triangular', G3_XZ24, route='list')
case('cubic', 'cubic', 'Cubic', CUBIC)
case('leopard', 'leopard', 'Leopard', G3)
case('onion', 'onion', 'Onion', G3)
case('radial', 'radial', 'Radial', NEAR_AXIS)
case('planar', 'planar', 'Planar', G3_PLANAR)
case('boxed', 'boxed', 'Boxed', G3_MORE)
case('spherical', 'spherical', 'Spherical', G3_MORE)
case('cylindrical', 'cylindrical', 'Cylindrical', G3_MORE)
case('quilted', 'quilted', 'Quilted { control0 = 1.; control1 = 1. }', G3_QUILT)
case('quilted 0.3 2.5', 'quilted control0 0.3 control1 2.5', 'Quilted { control0 = f32 0.3; control1 = f32 2.5 }', G3)
case('spiral1 5', 'spiral1 5', 'Spiral1 5', G3_AXIS, ramp=True)
case('spiral2 3', 'spiral2 3', 'Spiral2 3', G3_AXIS, ramp=True)
case('marble', 'marble', 'Marble', G3, ramp=True)
case('wood', 'wood', 'Wood', G3, ramp=True)


def fractal_ml(kind, it, exp=2, it_=0, et=1, ifac=1.0, efac=1.0):
    return ('Fractal { fkind = %s; iterations = %d; exponent = %d; interior_type = %d; exterior_type = %d; '
            'ifactor = %s; efactor = %s }' % (kind, it, exp, it_, et, ml_float(ifac), ml_float(efac)))


for e in [2, 3, 4, 5, 8]:
    case('mandel exponent %d' % e, 'mandel 30 exponent %d' % e, fractal_ml('Mandel', 30, e), FRAC)
for e in [2, 3, 4, 6]:
    case('julia exponent %d' % e, 'julia <0.353, 0.288>, 40 exponent %d' % e,
         fractal_ml('Julia (0.353, 0.288)', 40, e), FRAC)
case('mandel exponent 1 (as 2)', 'mandel 25 exponent 1', fractal_ml('Mandel', 25, 1), FRAC)
case('mandel exponent 40 (as 2)', 'mandel 25 exponent 40', fractal_ml('Mandel', 25, 40), FRAC)
for t in range(7):
    case('mandel interior %d' % t, 'mandel 30 interior %d, 1.3' % t, fractal_ml('Mandel', 30, 2, t, 1, 1.3), FRAC)
    case('julia exponent 3 interior %d' % t, 'julia <-0.2, 0.6>, 20 exponent 3 interior %d, 0.8' % t,
         fractal_ml('Julia ((-0.2), 0.6)', 20, 3, t, 1, 0.8), FRAC)
for t in range(7):
    case('mandel exterior %d' % t, 'mandel 30 exterior %d, 0.7' % t, fractal_ml('Mandel', 30, 2, 0, t, 1.0, 0.7), FRAC)
    case('mandel exponent 7 exterior %d' % t, 'mandel 15 exponent 7 exterior %d, 2.5' % t,
         fractal_ml('Mandel', 15, 7, 0, t, 1.0, 2.5), FRAC)
for t, ef in [(7, 5.0), (7, 3.7), (8, 4.0), (8, 6.5)]:
    case('mandel exterior %d, %g' % (t, ef), 'mandel 30 exterior %d, %r' % (t, ef),
         fractal_ml('Mandel', 30, 2, 0, t, 1.0, ef), FRAC, route='pigment')
for n in [1, 2]:
    for t, et in [(0, 1), (1, 2), (4, 6), (6, 3)]:
        case('magnet %d mandel interior %d exterior %d' % (n, t, et),
             'magnet %d mandel 20 interior %d, 1.5 exterior %d, 0.9' % (n, t, et),
             fractal_ml('Magnet_mandel %d' % n, 20, 0, t, et, 1.5, 0.9), MAGNET)
        case('magnet %d julia interior %d exterior %d' % (n, t, et),
             'magnet %d julia <0.4, -0.2>, 20 interior %d, 1.5 exterior %d, 0.9' % (n, t, et),
             fractal_ml('Magnet_julia (%d, (0.4, (-0.2)))' % n, 20, 0, t, et, 1.5, 0.9), MAGNET)

for n in range(1, 28):
    case('tiling %d' % n, 'tiling %d' % n, 'Tiling %d' % n, XZ200 if n >= 25 else XZ, route='pigment')

valid = {3: [1, 1, 1, 3, 4, 12], 4: [1, 1, 2, 5, 12, 35], 6: [1, 1, 3, 7, 22]}


def pavement_ml(side, tile, number, form=0, interior=0, exterior=0):
    return ('Pavement { side = %d; tile = %d; number = %d; exterior = %d; interior = %d; form = %d }'
            % (side, tile, number, exterior, interior, form))


for side, counts in valid.items():
    for tile, count in enumerate(counts, 1):
        for number in range(1, count + 1):
            case('pavement %d %d %d' % (side, tile, number),
                 'pavement number_of_sides %d number_of_tiles %d pattern %d' % (side, tile, number),
                 pavement_ml(side, tile, number), XZ, route='pigment')
# the forms, interiors and exteriors, on patterns that have every kind of corner
for side, tile, number in [(4, 6, 2), (4, 4, 5), (4, 5, 7), (3, 6, 12), (3, 6, 4), (3, 2, 1), (6, 4, 2), (6, 5, 9), (6, 3, 3)]:
    forms = 4 if side == 4 else 3
    for form in range(forms):
        for interior in range(3):
            for exterior in range(3):
                if side == 6 and exterior:
                    continue
                if form == 0 and interior == 0 and exterior == 0:
                    continue
                case('pavement %d %d %d form %d interior %d exterior %d' % (side, tile, number, form, interior, exterior),
                     'pavement number_of_sides %d number_of_tiles %d pattern %d form %d interior %d exterior %d'
                     % (side, tile, number, form, interior, exterior),
                     pavement_ml(side, tile, number, form, interior, exterior), XZ24, route='pigment')

# -- patterns with noise ------------------------------------------------------------------------
for g in [1, 2, 3]:
    case('bozo, generator %d' % g, 'bozo noise_generator %d' % g, 'Bozo', G3, suite='noise', gen=g)
case('spotted', 'spotted', 'Spotted', G3, suite='noise')
case('bumps', 'bumps noise_generator 3', 'Bumps', G3, suite='noise', gen=3)
for g in [1, 2, 3]:
    case('granite, generator %d' % g, 'granite noise_generator %d' % g, 'Granite', G3, suite='noise', gen=g)
    case('wrinkles, generator %d' % g, 'wrinkles noise_generator %d' % g, 'Wrinkles', G3, suite='noise', gen=g)
case('dents', 'dents', 'Dents', G3, suite='noise')
case('cells', 'cells', 'Cells', G3_CELLS, suite='noise')


def turb_ml(amount, octaves=6, omega=0.5, lam=2.0):
    return ('[ Classic_turb { turbulence = v %s %s %s; octaves = %d; omega = f32 %s; lambda = f32 %s } ]'
            % (ml_float(amount[0]), ml_float(amount[1]), ml_float(amount[2]), octaves, ml_float(omega), ml_float(lam)))


case('agate', 'agate', 'Agate 1.', G3, suite='noise', warps=turb_ml((0, 0, 0)))
case('agate, agate_turb 0.6, octaves 4, omega 0.6, lambda 2.5',
     'agate agate_turb 0.6 octaves 4 omega 0.6 lambda 2.5', 'Agate (f32 0.6)', G3, suite='noise',
     warps=turb_ml((0, 0, 0), 4, 0.6, 2.5), gen=2)
case('agate, turbulence 0.4 (warped), generator 3', 'agate turbulence 0.4 noise_generator 3', 'Agate 1.', G3,
     suite='noise', warps=turb_ml((0.4, 0.4, 0.4)), gen=3)
case('marble, turbulence 0.5', 'marble turbulence 0.5', 'Marble', G3, suite='noise', warps=turb_ml((0.5, 0.5, 0.5)), ramp=True)
case('marble, turbulence <0.8,0,0>, octaves 3, generator 1', 'marble turbulence <0.8, 0, 0> octaves 3 noise_generator 1',
     'Marble', G3, suite='noise', warps=turb_ml((0.8, 0, 0), 3), gen=1, ramp=True)
case('wood, turbulence <0.3,0.2,0.1>', 'wood turbulence <0.3, 0.2, 0.1>', 'Wood', G3, suite='noise',
     warps=turb_ml((0.3, 0.2, 0.1)), ramp=True)
case('spiral1 4, turbulence 0.3 (warped)', 'spiral1 4 turbulence 0.3', 'Spiral1 4', G3, suite='noise',
     warps=turb_ml((0.3, 0.3, 0.3)), ramp=True)
case('spiral2 2, turbulence <0.2,0.5,0.1> (warped)', 'spiral2 2 turbulence <0.2, 0.5, 0.1>', 'Spiral2 2', G3,
     suite='noise', warps=turb_ml((0.2, 0.5, 0.1)), ramp=True)
case('waves', 'waves', 'Waves', G3, suite='noise', freq=1.0, phase=0.0, ramp=True)
case('ripples', 'ripples', 'Ripples', G3, suite='noise', freq=1.0, phase=0.0, ramp=True)
case('waves, frequency 2.5, phase 0.3', 'waves frequency 2.5 phase 0.3', 'Waves', G3, suite='noise', freq=2.5, phase=0.3, ramp=True)
case('ripples, frequency 0.7, phase -0.45', 'ripples frequency 0.7 phase -0.45', 'Ripples', G3, suite='noise', freq=0.7, phase=-0.45, ramp=True)


def crackle_ml(form=(-1, 1, 0), metric=2.0, offset=0.0, solid=False):
    return ('Crackle { form = v %s %s %s; metric = %s; offset = %s; solid = %s }'
            % (ml_float(form[0]), ml_float(form[1]), ml_float(form[2]), ml_float(metric), ml_float(offset),
               'true' if solid else 'false'))


case('crackle', 'crackle', crackle_ml(), CR, suite='noise')
case('crackle form <1,0,0>', 'crackle form <1, 0, 0>', crackle_ml((1, 0, 0)), CR, suite='noise')
case('crackle form <0,0,1>', 'crackle form <0, 0, 1>', crackle_ml((0, 0, 1)), CR, suite='noise')
case('crackle form <0.8,-0.3,0.6> offset 0.2', 'crackle form <0.8, -0.3, 0.6> offset 0.2',
     crackle_ml((0.8, -0.3, 0.6), 2, 0.2), CR, suite='noise')
case('crackle metric 1', 'crackle metric 1', crackle_ml(metric=1.0), CR, suite='noise')
case('crackle metric 1 form <1,0,0> offset 0.1', 'crackle metric 1 form <1, 0, 0> offset 0.1',
     crackle_ml((1, 0, 0), 1.0, 0.1), CR, suite='noise')
case('crackle metric 3 form <1,-0.5,0.25>', 'crackle metric 3 form <1, -0.5, 0.25>',
     crackle_ml((1, -0.5, 0.25), 3.0), CR, suite='noise')
case('crackle metric 0.7 offset 0.3', 'crackle metric 0.7 offset 0.3', crackle_ml(metric=0.7, offset=0.3), CR, suite='noise')
case('crackle solid', 'crackle solid', crackle_ml(solid=True), CR, suite='noise')
case('crackle solid metric 1, generator 1', 'crackle solid metric 1 noise_generator 1',
     crackle_ml(metric=1.0, solid=True), CR, suite='noise', gen=1)
case('crackle solid metric 2.5, generator 3', 'crackle solid metric 2.5 noise_generator 3',
     crackle_ml(metric=2.5, solid=True), CR, suite='noise', gen=3)


# -- running POV-Ray ----------------------------------------------------------------------------
C = Fraction(1.00001)
HEADER = ('// Written by gen.py (beside it); run: povray +I%s +O/tmp/t.png +W8 +H6 -D  (values go to #debug)\n'
          '#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location -z look_at 0 }\n')


def point_sets_decl():
    lines = []
    for name, s in POINT_SETS:
        lines.append('#declare P_%s = array[%d] {\n  %s }' % (name, len(s), ',\n  '.join('<%r, %r, %r>' % tuple(float(c) for c in q) for q in s)))
    return lines


def run(name, lines):
    path = os.path.join(HERE, name)
    with open(path, 'w') as f:
        f.write(HEADER % name)
        f.write('\n'.join(point_sets_decl() + lines) + '\n')
    r = subprocess.run(['povray', '+I' + name, '+O/tmp/pattern_values.png', '+W8', '+H6', '-D'], cwd=HERE,
                       capture_output=True, text=True)
    out = {}
    for line in (r.stdout + r.stderr).splitlines():
        if line.startswith('V '):
            _, key, val = line.split(' ')
            out[key] = val
    if not out:
        sys.exit('no values from %s:\n%s' % (name, r.stderr[-3000:]))
    return out


def pattern_modifiers(c):
    mods = ' frequency 0' if c['freq'] is None else ''  # else the frequency and phase are in the text
    if c['ramp']:
        mods += ' ramp_wave'
    return mods


def loop(k, c, function, value):
    ps = 'P_' + set_name(c['points'])
    return ['#for (I, 0, %d)' % (len(c['points']) - 1)] + function + [
        '  #debug concat("V %d.", str(I, 0, 0), " ", str(%s, 0, 20), "\\n")' % (k, value % (ps, ps, ps)), '#end']


def scene_pattern_route(cs):
    lines = []
    for k, c in enumerate(cs):
        lines.append('// %s' % c['label'])
        lines.append('#declare F%d = function { pattern { %s%s } }' % (k, c['pov'], pattern_modifiers(c)))
        lines += loop(k, c, [], 'F%d(%%s[I].x, %%s[I].y, %%s[I].z)' % k)
    return lines


def scene_pigment_route(cs, freqs):
    """[freqs] is None or, per case, the frequency of each point"""
    lines = []
    for k, c in enumerate(cs):
        lines.append('// %s' % c['label'])
        if c['route'] == 'list':
            lines.append('#declare F%d = function { pigment { %s } }' % (k, c['pov']))
            lines += loop(k, c, [], 'F%d(%%s[I].x, %%s[I].y, %%s[I].z).red' % k)
        else:
            if freqs is None:
                lines.append('#declare F%d = function { pigment { %s color_map { [0 rgb 0] [1 rgb 1] } } }' % (k, c['pov']))
                lines += loop(k, c, [], 'F%d(%%s[I].x, %%s[I].y, %%s[I].z).red' % k)
            else:
                fs = freqs[k]
                lines.append('#declare E = array[%d] { %s }' % (len(fs), ', '.join(fs)))
                body = loop(k, c, ['  #declare F = function { pigment { %s color_map { [0 rgb 0] [1 rgb 1] } frequency E[I] } }' % c['pov']],
                            'F(%s[I].x, %s[I].y, %s[I].z).red')
                lines += body[:-1] + ['  #undef F', '#end', '#undef E']
    return lines


def pow2(e):
    return '%r' % float(2.0 ** e)


def refine(prev, red, F):
    """the v whose fmod(v F, 1.00001), rounded to a float, is [red], nearest [prev]"""
    red = Fraction(red)
    n0 = math.floor(Fraction(prev) * F / C)
    best = None
    for n in range(n0 - 2, n0 + 3):
        if n < 0:
            continue
        v = (n * C + red) / F
        if best is None or abs(v - Fraction(prev)) < abs(best - Fraction(prev)):
            best = v
    return float(best)


values = {}
pattern_cases = [c for c in cases if c['route'] == 'pattern']
out = run('pattern_values.pov', scene_pattern_route(pattern_cases))
for k, c in enumerate(pattern_cases):
    values[id(c)] = [out['%d.%d' % (k, i)] for i in range(len(c['points']))]

list_cases = [c for c in cases if c['route'] == 'list']
out = run('pattern_values_list.pov', scene_pigment_route(list_cases, None))
for k, c in enumerate(list_cases):
    values[id(c)] = [out['%d.%d' % (k, i)] for i in range(len(c['points']))]

pig = [c for c in cases if c['route'] == 'pigment']
keys = [(k, i) for k, c in enumerate(pig) for i in range(len(c['points']))]
out1 = run('pattern_values_f1.pov', scene_pigment_route(pig, None))
est = {key: float(out1['%d.%d' % key]) for key in keys}
expo = {key: (math.frexp(est[key])[1] - 1 if est[key] > 0 else -60) for key in keys}
for stage, shift in [(2, 16), (3, 30)]:
    freqs = [[pow2(shift - expo[(k, i)]) for i in range(len(c['points']))] for k, c in enumerate(pig)]
    out = run('pattern_values_f%d.pov' % stage, scene_pigment_route(pig, freqs))
    for key in keys:
        red = float(out['%d.%d' % key])
        if red == 1.0:
            print('warning: %s point %d: the remainder is in [1, 1.00001) at stage %d' % (pig[key[0]]['label'], key[1], stage))
        est[key] = refine(est[key], red, Fraction(2) ** (shift - expo[key]))
for k, c in enumerate(pig):
    values[id(c)] = [repr(est[(k, i)]) for i in range(len(c['points']))]

# -- the OCaml data -------------------------------------------------------------------------------
def ml_row(items, per, indent):
    rows = []
    for i in range(0, len(items), per):
        rows.append(' ' * indent + '; '.join(items[i:i + per]) + ';')
    return '\n'.join(rows)


with open(OUT_ML, 'w') as f:
    f.write('(* POV-Ray 3.7.0.10\'s pattern values, printed by the scenes in test/unit/data/pattern_values/\n'
            '   and written by gen.py there (do not edit: run it again). Each case is a pattern as POV-Ray\n'
            '   stores it, its warps (for the classic turbulence), its noise generator, how the value was\n'
            '   printed, the points and POV-Ray\'s value at each. *)\n\n')
    f.write('open Povml\n\n')
    f.write('type route =\n  | Raw  (** a pattern function with frequency 0: the raw value, a negative one v as v - floor v *)\n'
            '  | Wrapped of float * float\n      (** a pattern function with this frequency and phase: fmod(v f + p, 1.00001), wrapped *)\n'
            '  | Exact  (** reconstructed from pigment functions: the raw value *)\n\n')
    f.write('type case = {\n  label : string;\n  pattern : Scene.pattern;\n  warps : Scene.warp list;\n  gen : int;\n'
            '  route : route;\n  points : Vec.t array;\n  values : float array;  (** POV-Ray\'s, one per point *)\n}\n\n')
    f.write('let v = Vec.make\nlet f32 = Precision.f32\n\n')
    for name, s in POINT_SETS:
        f.write('let %s =\n  [|\n%s\n  |]\n\n' % (name, ml_row(['v %s %s %s' % tuple(ml_float(c) for c in q) for q in s], 4, 4)))
    for suite in ['plain', 'noise']:
        f.write('let %s : case list =\n  Scene.\n    [\n' % suite)
        for c in cases:
            if c['suite'] != suite:
                continue
            if c['route'] in ('pigment', 'list'):
                route = 'Exact'
            elif c['freq'] is None:
                route = 'Raw'
            else:
                route = 'Wrapped (f32 %s, f32 %s)' % (ml_float(c['freq']), ml_float(c['phase']))
            f.write('      {\n        label = %s;\n        pattern = %s;\n        warps = %s;\n        gen = %d;\n'
                    '        route = %s;\n        points = %s;\n        values =\n          [|\n'
                    % ('"' + c['label'] + '"', c['ml'], c['warps'], c['gen'], route, set_name(c['points'])))
            f.write(ml_row([ml_float(float(val)) for val in values[id(c)]], 5, 12))
            f.write('\n          |];\n      };\n')
        f.write('    ]\n\n')
print('%d cases, %d values' % (len(cases), sum(len(c['points']) for c in cases)))
