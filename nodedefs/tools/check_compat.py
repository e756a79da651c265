#!/usr/bin/env python3
"""Check mxc's node library against MaterialX's node definitions.

Usage:  python3 nodedefs/tools/check_compat.py [--mx <MaterialX libraries dir>] [-v]

Compares, per library, every nodedef of MaterialX with ours: presence, nodedef
attributes, input/output/token order and names, types, default values (numeric
types compared numerically), defaultgeomprop, uniform, enum/enumvalues, units,
colorspace, UI limits and folders.  Also compares typedefs, unit definitions and
geompropdefs, checks well-formedness and nodedef counts, and flags doc strings
that are identical to MaterialX's (house rule: no copied prose).

Exit status is 1 if any difference is found that is not in ALLOWED below.
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
OURS = os.path.dirname(HERE)
DEFAULT_MX = '/work/shared/reference/materialx/libraries'

# Each of our files (relative to nodedefs/) and MaterialX's counterpart (relative to libraries/).
LIBRARIES = [
    ('stdlib/stdlib_defs.mtlx', 'stdlib/stdlib_defs.mtlx'),
    ('pbrlib/pbrlib_defs.mtlx', 'pbrlib/pbrlib_defs.mtlx'),
    ('cmlib/cmlib_defs.mtlx', 'cmlib/cmlib_defs.mtlx'),
    ('nprlib/nprlib_defs.mtlx', 'nprlib/nprlib_defs.mtlx'),
    ('lights/lights_defs.mtlx', 'lights/lights_defs.mtlx'),
    ('bxdf/standard_surface.mtlx', 'bxdf/standard_surface.mtlx'),
    ('bxdf/open_pbr_surface.mtlx', 'bxdf/open_pbr_surface.mtlx'),
]

# Accepted differences: (nodedef or element name, location) -> one-line reason.
ALLOWED = {
    ('ND_open_pbr_anisotropy', 'nodedef'):
        'helper used only inside MaterialX\'s OpenPBR nodegraph; mxc lowers OpenPBR in C++ and ships no nodegraph',
    ('ND_open_pbr_surface_surfaceshader', 'input emission_color @uimax'):
        'OpenPBR 1.1.1 parameter table gives emission_color the range [0, inf)^3 (HDR, changelog #260); MaterialX still caps the UI at 1',
    ('ND_standard_surface_surfaceshader_100', 'input transmission_scatter_anisotropy @uimin'):
        'Standard Surface spec ("Specular transmission") gives range [-1,1]; MaterialX uses uimin 0',
}

NUMERIC = {'float': 1, 'integer': 1, 'color3': 3, 'color4': 4, 'vector2': 2, 'vector3': 3, 'vector4': 4,
           'matrix33': 9, 'matrix44': 16}
IGNORED_ATTRS = {'doc', 'uiname'}          # prose and labels: deliberately not carried over
TYPED_ATTRS = {'value', 'default', 'uimin', 'uimax', 'uisoftmin', 'uisoftmax'}
LIST_ATTRS = {'enum'}
BOOL_DEFAULT_FALSE = {'uniform', 'uiadvanced', 'isdefaultversion'}


def parse_floats(s):
    try:
        return [float(x) for x in s.split(',')]
    except ValueError:
        return None


def same_numbers(a, b):
    return len(a) == len(b) and all(abs(x - y) <= 1e-9 * max(1.0, abs(x), abs(y)) for x, y in zip(a, b))


def same_value(typ, a, b):
    if a is None or b is None:
        return a is None and b is None
    if typ in NUMERIC:
        fa, fb = parse_floats(a), parse_floats(b)
        if fa is not None and fb is not None:
            return same_numbers(fa, fb)
    if typ == 'boolean':
        return a.strip().lower() == b.strip().lower()
    return a == b


def same_attr(key, typ, a, b):
    if key in BOOL_DEFAULT_FALSE:
        return (a or 'false').lower() == (b or 'false').lower()
    if key in TYPED_ATTRS:
        return same_value(typ, a, b)
    if key == 'enumvalues':
        if a is None or b is None:
            return a is None and b is None
        fa, fb = parse_floats(a), parse_floats(b)
        if fa is not None and fb is not None:
            return same_numbers(fa, fb)
        return [x.strip() for x in a.split(',')] == [x.strip() for x in b.split(',')]
    if key in LIST_ATTRS:
        if a is None or b is None:
            return a is None and b is None
        return [x.strip() for x in a.split(',')] == [x.strip() for x in b.split(',')]
    return a == b


class Report:
    def __init__(self):
        self.diffs = []      # (owner, location, message, allowed_reason)

    def add(self, owner, location, message):
        self.diffs.append((owner, location, message, ALLOWED.get((owner, location))))


def compare_attrs(rep, owner, loc, typ, ours, mx, skip=()):
    for key in sorted(set(ours.attrib) | set(mx.attrib)):
        if key in IGNORED_ATTRS or key in skip:
            continue
        a, b = ours.get(key), mx.get(key)
        if not same_attr(key, typ, a, b):
            rep.add(owner, '%s @%s' % (loc, key), 'ours=%r materialx=%r' % (a, b))


def compare_ports(rep, owner, ours, mx):
    for tag in ('input', 'output', 'token'):
        o_list = [e for e in ours if e.tag == tag]
        m_list = [e for e in mx if e.tag == tag]
        o_names = [e.get('name') for e in o_list]
        m_names = [e.get('name') for e in m_list]
        for n in m_names:
            if n not in o_names:
                rep.add(owner, '%s %s' % (tag, n), 'missing in ours')
        for n in o_names:
            if n not in m_names:
                rep.add(owner, '%s %s' % (tag, n), 'extra in ours')
        common_o = [n for n in o_names if n in m_names]
        common_m = [n for n in m_names if n in o_names]
        if common_o != common_m:
            rep.add(owner, '%s order' % tag, 'ours=%s materialx=%s' % (common_o, common_m))
        o_by = {e.get('name'): e for e in o_list}
        for e in m_list:
            n = e.get('name')
            if n in o_by:
                typ = e.get('type')
                compare_attrs(rep, owner, '%s %s' % (tag, n), typ, o_by[n], e)
    other = sorted({e.tag for e in list(ours) + list(mx)} - {'input', 'output', 'token'})
    for tag in other:
        rep.add(owner, 'child <%s>' % tag, 'unexpected child element kind')


def norm_prose(text):
    """Lower-case words only, so punctuation/case/spacing changes do not hide a copy."""
    return ' '.join(''.join(c if c.isalnum() else ' ' for c in text.lower()).split())


def check_docs(rep, owner, loc, ours, mx):
    a, b = ours.get('doc'), mx.get('doc')
    if a and b and norm_prose(a) == norm_prose(b):
        rep.add(owner, '%s @doc' % loc, 'doc string identical to MaterialX (must be our own wording)')


def keyed(root, tag, key='name'):
    return {e.get(key): e for e in root.iter(tag)}


def compare_library(rep, ours_path, mx_path):
    ours = ET.parse(ours_path).getroot()
    mx = ET.parse(mx_path).getroot()
    if ours.tag != 'materialx' or ours.get('version') != mx.get('version'):
        rep.add(os.path.basename(ours_path), 'materialx @version',
                'ours=%r materialx=%r' % (ours.get('version'), mx.get('version')))

    # Data-type, unit and geomprop declarations.
    for tag in ('typedef', 'unittypedef', 'unitdef', 'geompropdef'):
        o_map, m_map = keyed(ours, tag), keyed(mx, tag)
        for n in m_map:
            if n not in o_map:
                rep.add(n, tag, 'missing in ours')
        for n in o_map:
            if n not in m_map:
                rep.add(n, tag, 'extra in ours')
        for n, m in m_map.items():
            if n in o_map:
                compare_attrs(rep, n, tag, m.get('type'), o_map[n], m)
                check_docs(rep, n, tag, o_map[n], m)
                if tag == 'unitdef':
                    ou = [(u.get('name'), u.get('scale')) for u in o_map[n].iter('unit')]
                    mu = [(u.get('name'), u.get('scale')) for u in m.iter('unit')]
                    if [u[0] for u in ou] != [u[0] for u in mu] or not all(
                            same_numbers(parse_floats(a[1]), parse_floats(b[1])) for a, b in zip(ou, mu)):
                        rep.add(n, 'unitdef units', 'ours=%s materialx=%s' % (ou, mu))

    # Nodedefs.
    o_defs, m_defs = keyed(ours, 'nodedef'), keyed(mx, 'nodedef')
    if len(o_defs) != len(list(ours.iter('nodedef'))):
        rep.add(os.path.basename(ours_path), 'nodedef', 'duplicate nodedef names in ours')
    for n in m_defs:
        if n not in o_defs:
            rep.add(n, 'nodedef', 'missing in ours')
    for n in o_defs:
        if n not in m_defs:
            rep.add(n, 'nodedef', 'extra in ours')
    for n, m in m_defs.items():
        if n not in o_defs:
            continue
        o = o_defs[n]
        compare_attrs(rep, n, 'nodedef', None, o, m)
        check_docs(rep, n, 'nodedef', o, m)
        compare_ports(rep, n, o, m)
        o_in = {e.get('name'): e for e in o}
        for e in m:
            if e.get('name') in o_in:
                check_docs(rep, n, '%s %s' % (e.tag, e.get('name')), o_in[e.get('name')], e)
    return len(o_defs), len(m_defs)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--mx', default=DEFAULT_MX, help='MaterialX libraries directory')
    ap.add_argument('--ours', default=OURS, help='our nodedefs directory (default: this tree)')
    ap.add_argument('-v', '--verbose', action='store_true', help='also list allowed differences in detail')
    args = ap.parse_args()

    rep = Report()
    ok = True
    print('%-30s %8s %10s' % ('library', 'ours', 'materialx'))
    for ours_rel, mx_rel in LIBRARIES:
        ours_path = os.path.join(args.ours, ours_rel)
        mx_path = os.path.join(args.mx, mx_rel)
        try:
            n_ours, n_mx = compare_library(rep, ours_path, mx_path)
        except (ET.ParseError, OSError) as exc:
            print('ERROR %s: %s' % (ours_rel, exc))
            ok = False
            continue
        print('%-30s %8d %10d' % (ours_rel, n_ours, n_mx))

    failing = [d for d in rep.diffs if not d[3]]
    allowed = [d for d in rep.diffs if d[3]]
    for owner, loc, msg, _ in failing:
        print('DIFF  %s | %s | %s' % (owner, loc, msg))
    for owner, loc, msg, reason in allowed:
        print('ALLOW %s | %s | %s%s' % (owner, loc, reason, (' [%s]' % msg) if args.verbose else ''))
    used = {(d[0], d[1]) for d in allowed}
    for key in ALLOWED:
        if key not in used:
            print('STALE allow-list entry (no longer needed): %s | %s' % key)
            ok = False
    print('%d difference(s), %d allowed, %d failing' % (len(rep.diffs), len(allowed), len(failing)))
    return 0 if ok and not failing else 1


if __name__ == '__main__':
    sys.exit(main())
