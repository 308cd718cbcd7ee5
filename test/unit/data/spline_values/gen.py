#!/usr/bin/env python3
"""POV-Ray's spline values for test/unit/test_spline_values.ml.

Writes spline_values.pov beside this file (one #declare S<n> = spline { ... } per case), runs the
installed povray on it and writes test/unit/test_spline_values_data.ml with every value printed:
each spline at each of its times, called as S(t) and as S(t, linear_spline), S(t, quadratic_spline),
S(t, cubic_spline), S(t, natural_spline), printed term by term with str(v, 0, 20) (20 decimals,
which identify a double of magnitude above 1e-4; the test compares the printed strings).

Run from the repository root:  python3 test/unit/data/spline_values/gen.py
"""
import os, random, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, '..', '..', '..', '..'))
OUT_ML = os.path.join(ROOT, 'test', 'unit', 'test_spline_values_data.ml')
POV = os.path.join(HERE, 'spline_values.pov')
OUT_TXT = '/tmp/spline_values_out.txt'

KINDS = [None, 'linear_spline', 'quadratic_spline', 'cubic_spline', 'natural_spline']
ML_KIND = {None: 'Linear', 'linear_spline': 'Linear', 'quadratic_spline': 'Quadratic',
           'cubic_spline': 'Cubic', 'natural_spline': 'Natural'}
CALLS = [None, 'linear_spline', 'quadratic_spline', 'cubic_spline', 'natural_spline']


def lit(x):
    """A float literal both POV-Ray and OCaml read as the same double."""
    s = repr(float(x))
    return s


def ml_float(x):
    s = lit(x)
    return '(%s)' % s if s.startswith('-') else s


class Case:
    def __init__(self, label, entries, kind=None, base=None, sep=', ', between=', ', extra_times=(), preamble=''):
        """entries: [(time, value)] as written, value a float or a tuple of 2 to 5 floats, or a
        string (SDL text) with its OCaml value given as (text, floats)."""
        self.label, self.entries, self.kind, self.base, self.sep = label, entries, kind, base, sep
        self.between = between
        self.extra_times = list(extra_times)
        self.preamble = preamble

    def value_text(self, v):
        if isinstance(v, tuple) and len(v) == 2 and isinstance(v[0], str):
            return v[0]
        if isinstance(v, (int, float)):
            return lit(v)
        return '<' + ', '.join(lit(c) for c in v) + '>'

    def value_ml(self, v):
        if isinstance(v, tuple) and len(v) == 2 and isinstance(v[0], str):
            v = v[1]
        if isinstance(v, (int, float)):
            v = (v,)
        return '[| ' + '; '.join(ml_float(c) for c in v) + ' |]'

    def width(self, v):
        if isinstance(v, tuple) and len(v) == 2 and isinstance(v[0], str):
            v = v[1]
        return 2 if isinstance(v, (int, float)) else max(2, len(v))

    def block(self, name_of):
        items = []
        if self.base is not None:
            items.append(name_of(self.base))
        if self.kind:
            items.append(self.kind)
        written = [lit(t) + self.sep + self.value_text(v) for t, v in self.entries]
        return '{ ' + ' '.join(items + [self.between.join(written)]).strip() + ' }'

    def times(self, all_cases):
        ts = [t for t, _ in self.entries]
        if self.base is not None:
            ts += [t for t, _ in all_cases[self.base].all_entries(all_cases)]
        ts = sorted(set(ts))
        out = [ts[0] - 1.0, ts[0]]
        for a, b in zip(ts, ts[1:]):
            out += [a + (b - a) * 0.25, (a + b) / 2, a + (b - a) * 0.8, b]
        out += [ts[-1] + 0.5]
        out += self.extra_times
        seen, res = set(), []
        for t in out:
            if t not in seen:
                seen.add(t)
                res.append(t)
        return res

    def all_entries(self, all_cases):
        base = all_cases[self.base].all_entries(all_cases) if self.base is not None else []
        return base + list(self.entries)

    def terms(self, all_cases):
        w = max([self.width(v) for _, v in self.entries] + [2])
        if self.base is not None:
            w = max(w, all_cases[self.base].terms(all_cases))
        return w

    def kind_ml(self, all_cases):
        if self.kind is None and self.base is not None:
            return all_cases[self.base].kind_ml(all_cases)
        return ML_KIND[self.kind]


rng = random.Random(11)


def rv(n):
    return tuple(round(rng.uniform(-6, 6), 3) for _ in range(n))


P1 = [(2.0, (1.0, 2.0, 3.0))]
P2 = [(0.0, (1.0, -2.0)), (1.5, (4.0, 3.0))]
P3 = [(-1.0, (0.5, 2.0, -3.0)), (0.25, (3.0, -1.0, 2.0)), (2.0, (1.0, 4.0, 0.75))]
P4 = [(0.0, (1.0, 2.0, 3.0, 4.0)), (1.0, (2.0, 0.0, 1.0, 5.0)), (3.0, (-1.0, 3.0, 2.0, 2.0)), (3.5, (4.0, 1.0, 0.0, -2.0))]
P9 = [(t, rv(5)) for t in [-2.0, -1.25, 0.0, 0.3, 1.0, 2.75, 3.0, 4.5, 7.0]]
P14 = [(t, rv(3)) for t in sorted(round(rng.uniform(-9, 9), 3) for _ in range(14))]

cases = []
for pts, name in [(P1, '1 point'), (P2, '2 points'), (P3, '3 points'), (P4, '4 points'), (P9, '9 points'), (P14, '14 random points')]:
    for k in KINDS:
        cases.append(Case('%s, %s' % (name, k or 'default kind'), pts, kind=k))

FLOATS = [(0.0, 1.0), (1.0, 3.0), (2.5, -2.0), (4.0, 0.5), (5.0, 2.25)]
for k in KINDS:
    cases.append(Case('floats, %s' % (k or 'default kind'), FLOATS, kind=k))
cases.append(Case('floats, no commas', [(0.0, 1.0), (1.0, 3.0), (2.5, 0.25), (4.0, 2.0)], kind='natural_spline',
                  sep=' ', between=' '))
cases.append(Case('no comma between entries', [(0.0, (1.0, 2.0)), (1.0, (3.0, 0.5)), (2.0, (0.0, 1.0))],
                  kind='quadratic_spline', between='  '))
cases.append(Case('unsorted', [(3.0, (1.0, 2.0, 3.0)), (1.0, (4.0, -1.0, 0.5)), (0.0, (2.0, 2.0, 2.0)),
                               (2.0, (-3.0, 1.0, 1.0)), (5.0, (0.0, 0.5, 7.0)), (-1.5, (1.0, 1.0, -1.0))],
                  kind='cubic_spline'))
cases.append(Case('unsorted, natural', [(3.0, 1.0), (1.0, 4.0), (0.0, 2.0), (2.0, -3.0), (5.0, 0.0), (-1.5, 1.0)],
                  kind='natural_spline'))
cases.append(Case('duplicate in the middle replaces', [(0.0, (1.0, 1.0)), (1.0, (2.0, 5.0)), (2.0, (0.0, 3.0)),
                                                       (3.0, (1.0, 1.0)), (1.0, (7.0, -2.0))], kind='natural_spline'))
cases.append(Case('duplicate first replaces', [(0.0, (1.0, 1.0)), (1.0, (2.0, 5.0)), (2.0, (0.0, 3.0)),
                                               (0.0, (6.0, -4.0))], kind='quadratic_spline'))
cases.append(Case('duplicate of the last is lost', [(0.0, (1.0, 1.0)), (1.0, (2.0, 5.0)), (1.0, (9.0, 9.0)),
                                                    (2.0, (0.0, 3.0)), (3.0, (4.0, 4.0)), (3.0, (8.0, 8.0))],
                  kind='cubic_spline'))
cases.append(Case('duplicate of a single entry replaces', [(1.0, (1.0, 2.0)), (1.0, (3.0, 4.0))]))
cases.append(Case('duplicate of the last of two, then one after', [(0.0, 1.0), (2.0, 3.0), (2.0, 10.0), (1.0, 0.5),
                                                                   (2.0, 20.0)], kind='natural_spline'))
cases.append(Case('-1e6 after every time is lost', [(-2000000.0, 1.0), (-1000000.0, 5.0), (0.0, 3.0)]))
cases.append(Case('-1e6 first, then equal', [(-1000000.0, 1.0), (-1000000.0, 2.0), (1.0, 4.0)]))
cases.append(Case('wider value later: zeros below', [(0.0, (1.0, 2.0)), (1.0, (4.0, 5.0, 6.0))]))
cases.append(Case('float then 5 terms', [(0.0, 1.0), (1.0, (4.0, 5.0, 6.0, 7.0, 8.0))], kind='quadratic_spline'))
cases.append(Case('carry-over of the terms written before', [(0.0, (1.0, 2.0, 3.0, 4.0, 5.0)), (1.0, 1.0),
                                                              (2.0, (4.0, 5.0, 6.0, 7.0, 8.0)), (3.0, (-1.0, -2.0)),
                                                              (4.0, (2.0, 2.0, 2.0))], kind='natural_spline'))
cases.append(Case('carry-over in written order, unsorted', [(0.0, (1.0, 2.0, 3.0)), (3.0, 7.0), (1.0, (1.0, 1.0)),
                                                             (2.0, (9.0, 8.0, 7.0, 6.0)), (-1.0, 0.5)],
                  kind='cubic_spline'))
cases.append(Case('colour identifier values', [(0.0, ('C1', (0.20000000298023224, 0.4000000059604645, 0.6000000238418579,
                                                                0.800000011920929, 1.0))),
                                                (1.0, 2.0), (2.5, ('C2', (0.5, 0.25, 0.75, 0.0, 0.0)))],
                  kind='natural_spline',
                  preamble='#declare C1 = rgbft <0.2, 0.4, 0.6, 0.8, 1>;\n#declare C2 = rgb <0.5, 0.25, 0.75>;\n'))
cases.append(Case('big and small times', [(-1000.0, (1.0, 0.001)), (0.001, (2.0, 3.0)), (0.002, (2.5, 1.0)),
                                          (1000.0, (0.0, 1000.0)), (1e5, (3.0, 3.0))], kind='cubic_spline',
                  extra_times=[0.0015, 500.0, -999.5]))

# copies: spline { S<n> [kind] entries }
def index(label):
    return [c.label for c in cases].index(label)

cases.append(Case('copy as cubic', [], kind='cubic_spline', base=index('9 points, default kind')))
cases.append(Case('copy keeps natural', [], base=index('4 points, natural_spline')))
cases.append(Case('copy with entries, wider', [(0.5, (9.0, 9.0, 9.0, 9.0)), (10.0, (1.0, 2.0, 3.0, 4.0))],
                  base=index('3 points, natural_spline')))
cases.append(Case('copy: fresh buffer', [(20.0, 3.0), (30.0, 4.0)], kind='linear_spline',
                  base=index('carry-over of the terms written before')))
cases.append(Case('copy: duplicates', [(2.0, (5.0, 5.0, 5.0)), (0.25, (-7.0, 0.0, 1.0)), (-1.0, (2.0, 2.0, 2.0))],
                  kind='quadratic_spline', base=index('3 points, cubic_spline')))


def name_of(i):
    return 'S%d' % i


def write_pov():
    lines = ['// POV-Ray 3.7 spline values for test/unit/test_spline_values.ml (written by gen.py: run it again)',
             '#version 3.7;', 'global_settings { assumed_gamma 1 }', '']
    for i, c in enumerate(cases):
        if c.preamble:
            lines.append(c.preamble.rstrip('\n'))
        lines.append('// %s' % c.label)
        lines.append('#declare %s = spline %s' % (name_of(i), c.block(name_of)))
    lines.append('')
    lines.append('#fopen Out "%s" write' % OUT_TXT)
    # written inline: a five-term value passed to a macro would be declared, and so made a colour (single precision)
    for i, c in enumerate(cases):
        for j, t in enumerate(c.times(cases)):
            for m, call in enumerate(CALLS):
                arg = lit(t) + (', ' + call if call else '')
                lines.append('#write (Out, "V %d.%d.%d ", vstr(5, %s(%s), " ", 0, 20), "\\n")' % (i, m, j, name_of(i), arg))
    lines.append('#fclose Out')
    lines.append('sphere { 0, 1 pigment { rgb 1 } }')
    with open(POV, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def run():
    if os.path.exists(OUT_TXT):
        os.remove(OUT_TXT)
    r = subprocess.run(['povray', '+I' + POV, '+O/tmp/spline_values.png', '+W8', '+H6', '-D', '-V', '+WT1'],
                       cwd=HERE, capture_output=True, text=True, env=dict(os.environ, POVINI='/work/gen/empty.ini'))
    out = {}
    if os.path.exists(OUT_TXT):
        for line in open(OUT_TXT):
            if line.startswith('V '):
                parts = line.split()
                for k, val in enumerate(parts[2:]):
                    out['%s.%d' % (parts[1], k)] = val
    if not out:
        sys.exit('povray printed nothing:\n' + r.stderr[-3000:])
    return out


def write_ml(out):
    with open(OUT_ML, 'w') as f:
        f.write('(* POV-Ray 3.7.0.10\'s spline values, printed by test/unit/data/spline_values/spline_values.pov\n'
                '   and written by gen.py there (do not edit: run it again). Each case is a spline as written (its\n'
                '   block, the spline it copies, its kind and entries), its terms, the times it was called at and\n'
                '   POV-Ray\'s five printed terms at each time for S(t) and S(t, linear_spline), S(t, quadratic_spline),\n'
                '   S(t, cubic_spline), S(t, natural_spline). *)\n\n')
        f.write('type case = {\n  label : string;\n  name : string;  (** its identifier in the scene *)\n'
                '  preamble : string;  (** declarations the block uses *)\n'
                '  block : string;  (** the text after [spline], braces included *)\n'
                '  base : int option;  (** the case it copies *)\n  kind : Povml.Spline.kind;\n'
                '  entries : (float * float array) list;  (** as written *)\n  terms : int;\n'
                '  times : float array;\n'
                '  printed : string array array array;  (** [call][time][term], the calls S(t) then with each kind *)\n}\n\n')
        f.write('let cases =\n  [|\n')
        for i, c in enumerate(cases):
            ts = c.times(cases)
            printed = []
            for m in range(len(CALLS)):
                per_time = []
                for j in range(len(ts)):
                    per_time.append('[| ' + '; '.join('"%s"' % out['%d.%d.%d.%d' % (i, m, j, k)] for k in range(5)) + ' |]')
                printed.append('[|\n          ' + ';\n          '.join(per_time) + '\n        |]')
            f.write('    {\n')
            f.write('      label = %s;\n' % ('"' + c.label + '"'))
            f.write('      name = "%s";\n' % name_of(i))
            f.write('      preamble = %s;\n' % ('"' + c.preamble.replace('\n', '\\n').replace('"', '\\"') + '"'))
            f.write('      block = "%s";\n' % c.block(name_of).replace('"', '\\"'))
            f.write('      base = %s;\n' % ('None' if c.base is None else 'Some %d' % c.base))
            f.write('      kind = Povml.Spline.%s;\n' % c.kind_ml(cases))
            f.write('      entries = [ %s ];\n' % '; '.join('(%s, %s)' % (ml_float(t), c.value_ml(v)) for t, v in c.entries))
            f.write('      terms = %d;\n' % c.terms(cases))
            f.write('      times = [| %s |];\n' % '; '.join(ml_float(t) for t in ts))
            f.write('      printed =\n        [|\n        ' + ';\n        '.join(printed) + '\n        |];\n')
            f.write('    };\n')
        f.write('  |]\n')


if __name__ == '__main__':
    write_pov()
    write_ml(run())
