#!/usr/bin/env python3
"""Generate mxc's node-definition library (MaterialX 1.39 XML) from compact tables.

Run from anywhere:  python3 nodedefs/tools/generate_nodedefs.py

Every .mtlx file under nodedefs/{stdlib,pbrlib,cmlib,nprlib,lights,bxdf} is
rewritten deterministically from the signature tables below.  The tables are
hand-written: one row per node family, expanded over a list of type variants
following MaterialX's nodedef naming scheme (ND_<node>_<type>[FA|I|B|...]).

Table vocabulary
  fam(node, group, variants, inputs, outputs, doc, name=..., **nodedef_attrs)
  variants   list of (name-suffix, bindings); helpers V(...), FA(...), ONE
  i(...)     input:  name, type, value, g=defaultgeomprop, u=uniform, other attrs
  o(...)     output: type, default, di=defaultinput, name (default "out")
  "$X"       in a type/value/attribute is replaced by binding X of the variant
             ($T main type, $S second-argument type, $A noise amplitude type,
              $IN input type where it differs from the output type)
  I0 / I1    "identity for matrix types, otherwise 0 / 1"
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
NODEDEFS = os.path.dirname(HERE)

# --------------------------------------------------------------------------
# Types and value formatting
# --------------------------------------------------------------------------

F, I, B = 'float', 'integer', 'boolean'
C3, C4, V2, V3, V4, M3, M4 = 'color3', 'color4', 'vector2', 'vector3', 'vector4', 'matrix33', 'matrix44'
STR, FN = 'string', 'filename'
SS, DS, VS, LS = 'surfaceshader', 'displacementshader', 'volumeshader', 'lightshader'

NUM = [F, C3, C4, V2, V3, V4]        # float + the five tuple types
VEC = [C3, C4, V2, V3, V4]           # types that get "FA" (float second argument) variants
MAT = [M3, M4]

SIZE = {F: 1, I: 1, C3: 3, C4: 4, V2: 2, V3: 3, V4: 4, M3: 9, M4: 16}
AS_VECTOR = {C3: V3, C4: V4}

# Derived bindings: used when a variant does not bind the name explicitly.
DERIVED = {
    'S': lambda b: b['T'],
    'IN': lambda b: b['T'],
    'A': lambda b: F if b.get('S') == F else AS_VECTOR.get(b['T'], b['T']),
}


class Pick:
    """A default that depends on whether the resolved type is a matrix."""
    def __init__(self, matrix, other):
        self.matrix, self.other = matrix, other


IDENT = 'identity'
I0 = Pick(IDENT, 0)
I1 = Pick(IDENT, 1)


def fnum(x):
    return repr(float(x))


def fmt(typ, v):
    """Format a Python value as a MaterialX value string of type typ."""
    if v is None:
        return None
    if isinstance(v, Pick):           # empty for string, filename, shader and closure types
        v = v.matrix if typ in MAT else (v.other if typ in SIZE or typ == B else '')
    if typ == B:
        if isinstance(v, str):
            return v
        return 'true' if v else 'false'
    if typ == I:
        return str(int(v))
    if typ == F:
        return fnum(v) if not isinstance(v, str) else v
    if typ in SIZE:
        n = SIZE[typ]
        if isinstance(v, str):          # symbolic value, e.g. a geomprop name
            return v if v != IDENT else fmt(typ, IDENT_VALUES[typ])
        if not isinstance(v, (tuple, list)):
            v = (v,) * n
        assert len(v) == n, (typ, v)
        return ', '.join(fnum(x) for x in v)
    return str(v)                       # string, filename, shader and closure types


IDENT_VALUES = {
    M3: (1, 0, 0, 0, 1, 0, 0, 0, 1),
    M4: (1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),
}

# --------------------------------------------------------------------------
# Table helpers
# --------------------------------------------------------------------------

UI_VALUE_ATTRS = ('uimin', 'uimax', 'uisoftmin', 'uisoftmax')


def i(name, typ, value=None, g=None, u=False, **attrs):
    d = {'name': name, 'type': typ, 'value': value}
    if g:
        d['defaultgeomprop'] = g
    if u:
        d['uniform'] = 'true'
    d.update(attrs)
    return ('input', d)


def o(typ, default=None, di=None, name='out', u=False):
    d = {'name': name, 'type': typ, 'default': default}
    if di:
        d['defaultinput'] = di
    if u:
        d['uniform'] = 'true'
    return ('output', d)


def V(*types, **extra):
    return [('_' + t, dict(T=t, **extra)) for t in types]


def FA(*types):
    return [('_' + t + 'FA', dict(T=t, S=F)) for t in types]


ONE = [('', {})]


def resolve(x, b):
    if isinstance(x, str) and x.startswith('$'):
        key = x[1:]
        return b[key] if key in b else DERIVED[key](b)
    return x


class Library:
    def __init__(self, intro):
        self.intro = intro
        self.items = []          # ('comment', text) | ('elem', tag, attrs, children) | ('blank',)
        self.count = 0

    def section(self, title):
        self.items.append(('blank',))
        self.items.append(('comment', title))

    def elem(self, tag, attrs, children=()):
        self.items.append(('elem', tag, attrs, list(children)))

    def fam(self, node, group, variants, inputs, outputs, doc=None, name=None, **ndattrs):
        if not isinstance(outputs, list):
            outputs = [outputs]
        for suffix, b in variants:
            ndname = name or ('ND_' + node + suffix)
            attrs = {'name': ndname, 'node': node, 'nodegroup': group}
            attrs.update(ndattrs)
            if doc:
                attrs['doc'] = doc
            children = []
            for tag, spec in list(inputs) + list(outputs):
                d = {}
                typ = resolve(spec['type'], b)
                for k, v in spec.items():
                    v = resolve(v, b)
                    if k in ('value', 'default') or k in UI_VALUE_ATTRS:
                        v = fmt(typ, v)
                    elif k == 'type':
                        v = typ
                    if v is not None:
                        d[k] = v
                children.append((tag, d))
            self.elem('nodedef', attrs, children)
            self.count += 1


# --------------------------------------------------------------------------
# XML writer
# --------------------------------------------------------------------------

ATTR_ORDER = ['name', 'type', 'value', 'node', 'nodegroup', 'version', 'isdefaultversion', 'inherit',
              'bsdf', 'default', 'defaultinput', 'defaultgeomprop', 'uniform', 'enum', 'enumvalues',
              'unittype', 'unit', 'colorspace', 'uimin', 'uimax', 'uisoftmin', 'uisoftmax', 'uifolder',
              'uiadvanced', 'hint', 'semantic', 'context', 'geomprop', 'space', 'index', 'scale', 'doc']


def esc(s):
    return s.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;').replace('"', '&quot;')


def attr_text(attrs):
    unknown = set(attrs) - set(ATTR_ORDER)
    assert not unknown, unknown
    return ' '.join('%s="%s"' % (k, esc(str(attrs[k]))) for k in ATTR_ORDER if k in attrs)


def render(lib):
    assert not any('--' in line for line in lib.intro)
    out = ['<?xml version="1.0"?>', '<materialx version="1.39">', '  <!--']
    out += ['    ' + line if line else '' for line in lib.intro]
    out += ['  -->']
    for item in lib.items:
        if item[0] == 'blank':
            out.append('')
        elif item[0] == 'comment':
            assert '--' not in item[1]
            out.append('  <!-- %s -->' % item[1])
        else:
            _, tag, attrs, children = item
            if not children:
                out.append('  <%s %s />' % (tag, attr_text(attrs)))
            else:
                out.append('  <%s %s>' % (tag, attr_text(attrs)))
                for ctag, cattrs in children:
                    out.append('    <%s %s />' % (ctag, attr_text(cattrs)))
                out.append('  </%s>' % tag)
    out.append('</materialx>')
    return '\n'.join(out) + '\n'


def header(libfile, compat, extra=()):
    return ["mxc node library: %s" % libfile,
            "Generated by nodedefs/tools/generate_nodedefs.py; edit the tables there, not this file.",
            "Signature-compatible with MaterialX 1.39 %s" % compat,
            "(same nodedef names, node categories, inputs, outputs and default values)."] + list(extra)


# --------------------------------------------------------------------------
# Shared input groups
# --------------------------------------------------------------------------

ADDRESS = 'constant,clamp,periodic,mirror'
UV0 = i('texcoord', V2, g='UV0')
POBJ = i('position', V3, g='Pobject')
NWORLD = i('normal', V3, g='Nworld')
TWORLD = i('tangent', V3, g='Tworld')
BWORLD = i('bitangent', V3, g='Bworld')
FRAME_INPUTS = [
    i('filtertype', STR, 'linear', u=True, enum='closest,linear,cubic'),
    i('framerange', STR, '', u=True),
    i('frameoffset', I, 0, u=True),
    i('frameendaction', STR, 'constant', u=True, enum=ADDRESS),
]
LUMA_ACESCG = (0.2722287, 0.6740818, 0.0536895)
LUMA_REC709 = (0.2126, 0.7152, 0.0722)
LUMA_REC2020 = (0.2627, 0.6780, 0.0593)
LUMA = i('lumacoeffs', C3, LUMA_ACESCG, enum='acescg,rec709,rec2020,rec2100',
         enumvalues=', '.join(fmt(C3, c) for c in (LUMA_ACESCG, LUMA_REC709, LUMA_REC2020, LUMA_REC2020)))
SPACE = i('space', STR, 'object', u=True, enum='model,object,world')
ANGLE = dict(unittype='angle', unit='degree')
UNIT01 = dict(uimin=0, uimax=1)
SOFT01 = dict(uisoftmin=0, uisoftmax=1)


def hex_tiling_inputs():
    return [i('tiling', V2, 1), i('rotation', F, 1), i('rotationrange', V2, (0, 360)),
            i('scale', F, 1), i('scalerange', V2, (0.5, 2)), i('offset', F, 1),
            i('offsetrange', V2, (0, 1)), i('falloff', F, 0.5)]


# ==========================================================================
# stdlib
# ==========================================================================

def build_stdlib():
    L = Library(header('stdlib (standard data types and nodes)', 'libraries/stdlib/stdlib_defs.mtlx'))

    L.section('Data types')
    for t in ['boolean', 'integer', 'float']:
        L.elem('typedef', {'name': t})
    for t in ['color3', 'color4']:
        L.elem('typedef', {'name': t, 'semantic': 'color'})
    for t in ['vector2', 'vector3', 'vector4', 'matrix33', 'matrix44', 'string', 'filename', 'geomname']:
        L.elem('typedef', {'name': t})
    for t, ctx in [(SS, 'surface'), (DS, 'displacement'), (VS, 'volume'), (LS, 'light')]:
        L.elem('typedef', {'name': t, 'semantic': 'shader', 'context': ctx})
    L.elem('typedef', {'name': 'material', 'semantic': 'material'})
    L.elem('typedef', {'name': 'none'})
    for t in ['integer', 'float', 'color3', 'color4', 'vector2', 'vector3', 'vector4', 'string', 'geomname']:
        attrs = {'name': t + 'array'}
        if t.startswith('color'):
            attrs['semantic'] = 'color'
        L.elem('typedef', attrs)

    L.section('Units')
    L.elem('unittypedef', {'name': 'distance'})
    L.elem('unitdef', {'name': 'UD_stdlib_distance', 'unittype': 'distance'},
           [('unit', {'name': n, 'scale': s}) for n, s in [
               ('nanometer', '0.000000001'), ('micron', '0.000001'), ('millimeter', '0.001'),
               ('centimeter', '0.01'), ('inch', '0.0254'), ('foot', '0.3048'), ('yard', '0.9144'),
               ('meter', '1.0'), ('kilometer', '1000.0'), ('mile', '1609.344')]])
    L.elem('unittypedef', {'name': 'angle'})
    L.elem('unitdef', {'name': 'UD_stdlib_angle', 'unittype': 'angle'},
           [('unit', {'name': 'degree', 'scale': '1.0'}), ('unit', {'name': 'radian', 'scale': '57.295779513'})])

    L.section('Geometric properties usable as defaultgeomprop')
    for sp in ['object', 'world']:
        L.elem('geompropdef', {'name': 'P' + sp, 'type': V3, 'geomprop': 'position', 'space': sp})
        L.elem('geompropdef', {'name': 'N' + sp, 'type': V3, 'geomprop': 'normal', 'space': sp})
        L.elem('geompropdef', {'name': 'T' + sp, 'type': V3, 'geomprop': 'tangent', 'space': sp, 'index': '0'})
        L.elem('geompropdef', {'name': 'B' + sp, 'type': V3, 'geomprop': 'bitangent', 'space': sp, 'index': '0'})
    L.elem('geompropdef', {'name': 'UV0', 'type': V2, 'geomprop': 'texcoord', 'index': '0'})

    # ---------------------------------------------------------------- materials and shaders
    L.section('Materials and shaders')
    L.fam('surfacematerial', 'material', ONE,
          [i('surfaceshader', SS, ''), i('backsurfaceshader', SS, ''), i('displacementshader', DS, '')],
          o('material'), 'Material binding a front/back surface shader and a displacement shader.')
    L.fam('volumematerial', 'material', ONE, [i('volumeshader', VS, '')], o('material'),
          'Material binding a volume shader.')
    L.fam('surface_unlit', 'shader', ONE,
          [i('emission', F, 1), i('emission_color', C3, 1), i('transmission', F, 0),
           i('transmission_color', C3, 1), i('opacity', F, 1)],
          o(SS), 'Unlit surface: emission and transmission only.')

    # ---------------------------------------------------------------- textures
    L.section('Texture sampling')
    L.fam('image', 'texture2d', V(*NUM),
          [i('file', FN, '', u=True), i('layer', STR, '', u=True), i('default', '$T', 0), UV0,
           i('uaddressmode', STR, 'periodic', u=True, enum=ADDRESS),
           i('vaddressmode', STR, 'periodic', u=True, enum=ADDRESS)] + FRAME_INPUTS,
          o('$T', 0), 'Sample an image file at a texture coordinate.')
    L.fam('tiledimage', 'texture2d', V(*NUM),
          [i('file', FN, '', u=True), i('default', '$T', 0), UV0,
           i('uvtiling', V2, 1), i('uvoffset', V2, 0),
           i('realworldimagesize', V2, 1, unittype='distance'),
           i('realworldtilesize', V2, 1, unittype='distance')] + FRAME_INPUTS,
          o('$T', 0), 'Sample an image file repeated over UV space.')
    L.fam('latlongimage', 'texture2d', ONE,
          [i('file', FN, '', u=True), i('default', C3, 0), i('viewdir', V3, (0, 0, 1)),
           i('rotation', F, 0, uimin=0, uimax=360, **ANGLE)],
          o(C3, 0), 'Sample an equirectangular environment image by direction.', name='ND_latlongimage')
    L.fam('hextiledimage', 'texture2d', V(C3, C4),
          [i('file', FN, '', u=True), i('default', '$T', 0), UV0] + hex_tiling_inputs() +
          [i('falloffcontrast', F, 0.5), LUMA],
          o('$T', 0), 'Sample an image with randomized hexagonal tiling.')
    L.fam('triplanarprojection', 'texture3d', V(*NUM),
          [i('file' + a, FN, '', u=True) for a in 'xyz'] + [i('layer' + a, STR, '', u=True) for a in 'xyz'] +
          [i('default', '$T', 0), POBJ, i('normal', V3, g='Nobject'),
           i('upaxis', I, 2, u=True, enum='X,Y,Z', enumvalues='0,1,2'), i('blend', F, 1, **UNIT01)] +
          FRAME_INPUTS,
          o('$T', 0), 'Project three images along the object-space axes and blend them.')

    # ---------------------------------------------------------------- procedurals
    L.section('Procedural patterns')
    L.fam('constant', 'procedural', V(*NUM, B, I, M3, M4), [i('value', '$T', I0)], o('$T', I0),
          'Output a constant value.')
    L.fam('constant', 'procedural', V(STR, FN), [i('value', '$T', '', u=True)], o('$T', ''),
          'Output a constant value.')

    ramp = [UV0,
            i('type', I, 0, enum='standard,radial,circular,box', enumvalues='0,1,2,3'),
            i('interpolation', I, 1, enum='linear,smooth,step', enumvalues='0,1,2'),
            i('num_intervals', I, 2, uimin=2, uimax=10)]
    for k in range(1, 11):
        ramp += [i('interval%d' % k, F, 0 if k == 1 else 1, **UNIT01),
                 i('color%d' % k, C4, (0, 0, 0, 1) if k == 1 else 1, **UNIT01)]
    L.fam('ramp', 'procedural2d', ONE, ramp, o(C4), 'Multi-stop color ramp (up to ten stops).')
    L.fam('ramp_gradient', 'procedural2d', ONE,
          [i('x', F, 0, **UNIT01), i('interval1', F, 0, **UNIT01), i('interval2', F, 1, **UNIT01),
           i('color1', C4, (0, 0, 0, 1), **UNIT01), i('color2', C4, 1, **UNIT01),
           i('interpolation', I, 1, enum='linear,smooth,step', enumvalues='0,1,2'),
           i('prev_color', C4, (0, 0, 0, 1), **UNIT01), i('interval_num', I, 1), i('num_intervals', I, 2)],
          o(C4), 'One segment of a multi-stop ramp (helper for ramp).')
    for node, names, doc in [('ramplr', 'lr', 'Linear ramp from left to right in U.'),
                             ('ramptb', 'tb', 'Linear ramp from top to bottom in V.')]:
        L.fam(node, 'procedural2d', V(*NUM),
              [i('value' + names[0], '$T', 0), i('value' + names[1], '$T', 0), UV0], o('$T', 0), doc)
    L.fam('ramp4', 'procedural2d', V(*NUM),
          [i('value' + c, '$T', 0) for c in ('tl', 'tr', 'bl', 'br')] + [UV0], o('$T', 0),
          'Bilinear blend of four corner values.')
    for node, names, doc in [('splitlr', 'lr', 'Hard split between two values along U.'),
                             ('splittb', 'tb', 'Hard split between two values along V.')]:
        L.fam(node, 'procedural2d', V(*NUM),
              [i('value' + names[0], '$T', 0), i('value' + names[1], '$T', 0),
               i('center', F, 0.5, **UNIT01), UV0], o('$T', 0), doc)

    for dim, coord in [('2d', UV0), ('3d', POBJ)]:
        grp = 'procedural' + dim
        L.fam('noise' + dim, grp, V(*NUM) + FA(*VEC),
              [i('amplitude', '$A', 1), i('pivot', F, 0), coord], o('$T', 0),
              'Perlin noise, scaled by amplitude and offset by pivot.')
    for dim, coord in [('2d', UV0), ('3d', POBJ)]:
        grp = 'procedural' + dim
        L.fam('fractal' + dim, grp, V(*NUM) + FA(*VEC),
              [i('amplitude', '$A', 1), i('octaves', I, 3), i('lacunarity', F, 2), i('diminish', F, 0.5), coord],
              o('$T', 0), 'Fractal (multi-octave) Perlin noise.')
    L.fam('cellnoise2d', 'procedural2d', V(F), [UV0], o(F, 0), 'Cell noise: one random value per unit cell.')
    L.fam('cellnoise3d', 'procedural3d', V(F), [POBJ], o(F, 0), 'Cell noise: one random value per unit cell.')
    STYLE = i('style', I, 0, enum='Distance,Solid', enumvalues='0,1')
    L.fam('worleynoise2d', 'procedural2d', V(F, V2, V3), [UV0, i('jitter', F, 1), STYLE], o('$T', 0),
          'Worley (cellular distance) noise.')
    L.fam('worleynoise3d', 'procedural3d', V(F, V2, V3), [POBJ, i('jitter', F, 1), STYLE], o('$T', 0),
          'Worley (cellular distance) noise.')
    for dim, cname, ctype, cgeom in [('2d', 'texcoord', V2, 'UV0'), ('3d', 'position', V3, 'Pobject')]:
        common, post, fractal = 'Common', 'Post Process', 'Fractal'
        L.fam('unifiednoise' + dim, 'procedural' + dim, V(F),
              [i(cname, ctype, g=cgeom, uifolder=common), i('freq', ctype, 1, uifolder=common),
               i('offset', ctype, 0, uifolder=common), i('jitter', F, 1, uifolder=common, **SOFT01),
               i('outmin', F, 0, uifolder=post), i('outmax', F, 1, uifolder=post),
               i('clampoutput', B, True, uifolder=post), i('octaves', I, 3, uifolder=fractal),
               i('lacunarity', F, 2, uifolder=fractal), i('diminish', F, 0.5, uifolder=fractal, **SOFT01),
               i('type', I, 0, uifolder=common, uisoftmin=0, uisoftmax=3,
                 enum='Perlin,Cell,Worley,Fractal', enumvalues='0,1,2,3'),
               STYLE],
              o(F, 0), 'Single node exposing the Perlin, cell, Worley and fractal noises.')
    for dim, coord in [('2d', UV0), ('3d', POBJ)]:
        L.fam('flake' + dim, 'procedural' + dim, ONE,
              [i('size', F, 0.01), i('roughness', F, 0.1), i('coverage', F, 0.5), coord, NWORLD, TWORLD, BWORLD],
              [o(I, 0, name='id'), o(F, 0, name='rand'), o(F, 0, name='presence'),
               o(V3, 'Nworld', name='flakenormal')],
              'Randomly oriented glitter flakes.', name='ND_flake' + dim)
    L.fam('randomfloat', 'procedural', V(F, I),
          [i('in', '$T', 0), i('min', F, 0), i('max', F, 1), i('seed', I, 0)], o(F),
          'Hash an input to a random float in [min, max].')
    L.fam('randomcolor', 'procedural3d', V(F, I),
          [i('in', '$T', 0, uisoftmin=0, uisoftmax=10)] +
          [i(n, F, v, **SOFT01) for n, v in [('huelow', 0), ('huehigh', 1), ('saturationlow', 0.825),
                                             ('saturationhigh', 1), ('brightnesslow', 1), ('brightnesshigh', 1)]] +
          [i('seed', I, 0)],
          o(C3), 'Hash an input to a random color within HSV limits.')
    L.fam('checkerboard', 'procedural2d', V(C3),
          [i('color1', C3, 1), i('color2', C3, 0), i('uvtiling', V2, 8), i('uvoffset', V2, 0), UV0],
          o(C3), 'Two-color checker pattern.')
    L.fam('line', 'procedural2d', V(F),
          [UV0, i('center', V2, 0), i('radius', F, 0.1), i('point1', V2, 0.25), i('point2', V2, 0.75)],
          o(F), 'Mask of a line segment.')
    for node in ['circle', 'cloverleaf', 'hexagon']:
        L.fam(node, 'procedural2d', V(F), [UV0, i('center', V2, 0), i('radius', F, 0.5)], o(F),
              'Mask of a single %s shape.' % node)
    for node, knob, kv in [('grid', 'thickness', 0.05), ('crosshatch', 'thickness', 0.05),
                           ('tiledcircles', 'size', 0.5), ('tiledcloverleafs', 'size', 0.5),
                           ('tiledhexagons', 'size', 0.5)]:
        L.fam(node, 'procedural2d', V(C3),
              [UV0, i('uvtiling', V2, 1), i('uvoffset', V2, 0), i(knob, F, kv), i('staggered', B, False)],
              o(C3), 'Repeating %s pattern.' % node)

    # ---------------------------------------------------------------- geometric
    L.section('Geometric and application data')
    L.fam('position', 'geometric', V(V3), [SPACE], o(V3, 0), 'Surface position in the given space.')
    L.fam('normal', 'geometric', V(V3), [SPACE], o(V3, (0, 1, 0)), 'Surface normal in the given space.')
    L.fam('tangent', 'geometric', V(V3), [SPACE, i('index', I, 0, u=True)], o(V3, (1, 0, 0)),
          'Surface tangent in the given space.')
    L.fam('bitangent', 'geometric', V(V3), [SPACE, i('index', I, 0, u=True)], o(V3, (0, 0, 1)),
          'Surface bitangent in the given space.')
    L.fam('texcoord', 'geometric', V(V2, V3), [i('index', I, 0, u=True)], o('$T', 0),
          'Texture coordinate set.')
    L.fam('geomcolor', 'geometric', V(F, C3, C4), [i('index', I, 0, u=True)], o('$T', 0),
          'Vertex color set.')
    L.fam('geompropvalue', 'geometric', V(I, B, F, C3, C4, V2, V3, V4),
          [i('geomprop', STR, '', u=True), i('default', '$T', 0)], o('$T', 0),
          'Named primvar value, with a fallback.')
    L.fam('geompropvalueuniform', 'geometric', V(STR, FN),
          [i('geomprop', STR, '', u=True), i('default', '$T', '', u=True)], o('$T', '', u=True),
          'Named uniform primvar value, with a fallback.')
    L.fam('bump', 'geometric', V(V3),
          [i('height', F, 0, **SOFT01), i('scale', F, 1, **SOFT01), NWORLD, TWORLD, BWORLD], o(V3),
          'Perturb a normal by a scalar height.')
    L.fam('frame', 'application', V(F), [], o(F, 1), 'Current animation frame.')
    L.fam('time', 'application', V(F), [i('fps', F, 24)], o(F, 0), 'Current time in seconds.')

    # ---------------------------------------------------------------- math
    L.section('Math')
    for node, doc in [('add', 'Sum of two values.'), ('subtract', 'Difference in1 - in2.')]:
        L.fam(node, 'math', V(F, I, C3, C4, V2, V3, V4, M3, M4) + FA(*VEC, *MAT),
              [i('in1', '$T', I0), i('in2', '$S', 0)], o('$T', di='in1'), doc)
    for node, doc in [('multiply', 'Product of two values (matrix product for matrices).'),
                      ('divide', 'Quotient in1 / in2 (product with the inverse for matrices).')]:
        L.fam(node, 'math', V(F, C3, C4, V2, V3, V4, M3, M4) + FA(*VEC),
              [i('in1', '$T', I0), i('in2', '$S', I1)], o('$T', di='in1'), doc)
    L.fam('modulo', 'math', V(*NUM) + FA(*VEC), [i('in1', '$T', 0), i('in2', '$S', 1)], o('$T', di='in1'),
          'Floored remainder of in1 / in2.')
    L.fam('fract', 'math', V(*NUM), [i('in', '$T', 0)], o('$T', di='in'), 'Fractional part.')
    L.fam('invert', 'math', V(*NUM) + FA(*VEC), [i('in', '$T', 0), i('amount', '$S', 1)], o('$T', di='in'),
          'amount - in.')
    L.fam('absval', 'math', V(*NUM), [i('in', '$T', 0)], o('$T', di='in'), 'Absolute value.')
    for node in ['floor', 'ceil', 'round']:
        L.fam(node, 'math', V(*NUM) + [('_integer', dict(T=I, IN=F))], [i('in', '$IN', 0)], o('$T', di='in'),
              'Per-component %s.' % node)
    for node, doc in [('power', 'in1 raised to in2.'), ('safepower', 'in1 raised to in2, sign-safe.')]:
        L.fam(node, 'math', V(*NUM) + FA(*VEC), [i('in1', '$T', 0), i('in2', '$S', 1)], o('$T', di='in1'), doc)
    for t in [F, V2, V3, V4]:
        for node in ['sin', 'cos', 'tan', 'asin', 'acos']:
            L.fam(node, 'math', V(t), [i('in', '$T', 0)], o('$T', di='in'), 'Per-component %s (radians).' % node)
        L.fam('atan2', 'math', V(t), [i('iny', '$T', 0), i('inx', '$T', 1)], o('$T', di='iny'),
              'Per-component arctangent of iny/inx (radians).')
    for t in [F, V2, V3, V4]:
        L.fam('sqrt', 'math', V(t), [i('in', '$T', 0)], o('$T', di='in'), 'Square root.')
        L.fam('ln', 'math', V(t), [i('in', '$T', 1)], o('$T', di='in'), 'Natural logarithm.')
        L.fam('exp', 'math', V(t), [i('in', '$T', 0)], o('$T', di='in'), 'Natural exponential.')
    L.fam('sign', 'math', V(*NUM), [i('in', '$T', 0)], o('$T', di='in'), 'Per-component sign (-1, 0 or 1).')
    L.fam('clamp', 'math', V(*NUM) + FA(*VEC), [i('in', '$T', 0), i('low', '$S', 0), i('high', '$S', 1)],
          o('$T', di='in'), 'Clamp to [low, high].')
    for node in ['min', 'max']:
        L.fam(node, 'math', V(*NUM) + FA(*VEC), [i('in1', '$T', 0), i('in2', '$S', 0)], o('$T', di='in1'),
              'Per-component %simum.' % node)
    for node in ['mincomponent', 'maxcomponent']:
        L.fam(node, 'math', V(*VEC), [i('in', '$T', 0)], o(F, 0), 'Smallest/largest component.')
    L.fam('normalize', 'math', V(V2, V3, V4), [i('in', '$T', 0)], o('$T', di='in'), 'Unit-length vector.')
    L.fam('magnitude', 'math', V(V2, V3, V4), [i('in', '$T', 0)], o(F, 0), 'Vector length.')
    L.fam('distance', 'math', V(V2, V3, V4), [i('in1', '$T', 0), i('in2', '$T', 0)], o(F),
          'Distance between two points.')
    L.fam('dotproduct', 'math', V(V2, V3, V4), [i('in1', '$T', 0), i('in2', '$T', 0)], o(F, 0), 'Dot product.')
    L.fam('crossproduct', 'math', V(V3), [i('in1', V3, 0), i('in2', V3, 0)], o(V3, di='in1'), 'Cross product.')
    for node, dflt in [('transformpoint', 0), ('transformvector', 0), ('transformnormal', (0, 0, 1))]:
        L.fam(node, 'math', V(V3),
              [i('in', V3, dflt), i('fromspace', STR, '', u=True), i('tospace', STR, '', u=True)],
              o(V3, di='in'), 'Transform a %s between named spaces.' % node[len('transform'):])
    L.fam('transformmatrix', 'math',
          [('_vector2M3', dict(T=V2, M=M3)), ('_vector3', dict(T=V3, M=M3)),
           ('_vector3M4', dict(T=V3, M=M4)), ('_vector4', dict(T=V4, M=M4))],
          [i('in', '$T', 0), i('mat', '$M', IDENT)], o('$T', di='in'),
          'Multiply a vector by a matrix (homogeneous where sizes differ).')
    L.fam('normalmap', 'math', [('_float', dict(T=F)), ('_vector2', dict(T=V2))],
          [i('in', V3, (0.5, 0.5, 1)), i('scale', '$T', 1), NWORLD, TWORLD, BWORLD], o(V3, di='normal'),
          'Decode a tangent-space normal map value into a world-space normal.')
    L.fam('hextilednormalmap', 'math', V(V3),
          [i('file', FN, '', u=True), i('default', V3, (0.5, 0.5, 1)), UV0] + hex_tiling_inputs() +
          [i('strength', F, 1), i('flip_g', B, False), NWORLD, TWORLD, BWORLD],
          o(V3, (0.5, 0.5, 1)), 'Normal map sampled with randomized hexagonal tiling.')
    L.fam('transpose', 'math', V(*MAT), [i('in', '$T', IDENT)], o('$T', di='in'), 'Matrix transpose.')
    L.fam('determinant', 'math', V(*MAT), [i('in', '$T', IDENT)], o(F, 1), 'Matrix determinant.')
    L.fam('invertmatrix', 'math', V(*MAT), [i('in', '$T', IDENT)], o('$T', di='in'), 'Matrix inverse.')
    L.fam('rotate2d', 'math', V(V2), [i('in', V2, 0), i('amount', F, 0, **ANGLE)], o(V2, di='in'),
          'Rotate a 2D vector about the origin.')
    L.fam('rotate3d', 'math', V(V3), [i('in', V3, 0), i('amount', F, 0, **ANGLE), i('axis', V3, (0, 1, 0))],
          o(V3, di='in'), 'Rotate a 3D vector about an axis.')
    L.fam('place2d', 'math', V(V2),
          [i('texcoord', V2, 0), i('pivot', V2, 0), i('scale', V2, 1), i('rotate', F, 0, **ANGLE),
           i('offset', V2, 0), i('operationorder', I, 0, enum='SRT,TRS', enumvalues='0,1')],
          o(V2, di='texcoord'), 'Scale, rotate and offset a texture coordinate.')
    L.fam('trianglewave', 'math', V(F), [i('in', F, 0)], o(F), 'Triangle wave of period 1.')
    L.fam('reflect', 'math', V(V3), [i('in', V3, (1, 0, 0)), NWORLD], o(V3), 'Reflect a direction.')
    L.fam('refract', 'math', V(V3), [i('in', V3, (1, 0, 0)), NWORLD, i('ior', F, 1)], o(V3),
          'Refract a direction.')

    # ---------------------------------------------------------------- adjustment
    L.section('Adjustment')
    L.fam('remap', 'adjustment', V(*NUM) + FA(*VEC),
          [i('in', '$T', 0), i('inlow', '$S', 0), i('inhigh', '$S', 1), i('outlow', '$S', 0), i('outhigh', '$S', 1)],
          o('$T', di='in'), 'Linearly map [inlow, inhigh] to [outlow, outhigh].')
    L.fam('smoothstep', 'adjustment', V(*NUM) + FA(*VEC),
          [i('in', '$T', 0), i('low', '$S', 0), i('high', '$S', 1)], o('$T', di='in'),
          'Hermite step between low and high.')
    L.fam('luminance', 'adjustment', V(C3, C4), [i('in', '$T', 0), LUMA], o('$T', di='in'),
          'Grey-scale luminance using the given coefficients.')
    L.fam('rgbtohsv', 'adjustment', V(C3, C4), [i('in', '$T', 0)], o('$T', di='in'), 'RGB to HSV.')
    L.fam('hsvtorgb', 'adjustment', V(C3, C4), [i('in', '$T', 0)], o('$T', di='in'), 'HSV to RGB.')
    L.fam('contrast', 'adjustment', V(*NUM) + FA(*VEC),
          [i('in', '$T', 0), i('amount', '$S', 1), i('pivot', '$S', 0.5)], o('$T', di='in'),
          'Scale values about a pivot.')
    L.fam('range', 'adjustment', V(*NUM) + FA(*VEC),
          [i('in', '$T', 0), i('inlow', '$S', 0), i('inhigh', '$S', 1), i('gamma', '$S', 1),
           i('outlow', '$S', 0), i('outhigh', '$S', 1), i('doclamp', B, False)],
          o('$T', di='in'), 'Remap with a gamma curve and optional clamping.')
    L.fam('hsvadjust', 'adjustment', V(C3, C4), [i('in', '$T', 0), i('amount', V3, (0, 1, 1))], o('$T', di='in'),
          'Offset hue, scale saturation and value.')
    L.fam('saturate', 'adjustment', V(C3, C4), [i('in', '$T', 0), i('amount', F, 1), LUMA], o('$T', di='in'),
          'Adjust saturation around luminance.')
    L.fam('colorcorrect', 'adjustment', [('_color3', dict(T=C3, W=(1, 1, 1))), ('_color4', dict(T=C4, W=(1, 1, 1, 0)))],
          [i('in', '$T', '$W'), i('hue', F, 0, **SOFT01), i('saturation', F, 1, **SOFT01),
           i('gamma', F, 1, uisoftmin=0, uisoftmax=3), i('lift', F, 0, **SOFT01), i('gain', F, 1, **SOFT01),
           i('contrast', F, 1, **SOFT01), i('contrastpivot', F, 0.5, **SOFT01),
           i('exposure', F, 0, uisoftmin=-1, uisoftmax=1)],
          o('$T'), 'Combined hue/saturation/gamma/lift/gain/contrast/exposure correction.')

    # ---------------------------------------------------------------- compositing
    L.section('Compositing')
    L.fam('premult', 'compositing', V(C4), [i('in', C4, (0, 0, 0, 1))], o(C4, di='in'), 'Multiply RGB by alpha.')
    L.fam('unpremult', 'compositing', V(C4), [i('in', C4, (0, 0, 0, 1))], o(C4, di='in'), 'Divide RGB by alpha.')
    blend = [i('fg', '$T', 0), i('bg', '$T', 0), i('mix', F, 1)]
    for node in ['plus', 'minus', 'difference', 'burn', 'dodge', 'screen', 'overlay']:
        L.fam(node, 'compositing', V(F, C3, C4), blend, o('$T', di='bg'), 'Blend fg over bg: %s.' % node)
    for node in ['disjointover', 'in', 'mask', 'matte', 'out', 'over']:
        L.fam(node, 'compositing', V(C4), blend, o('$T', di='bg'), 'Alpha compositing operator: %s.' % node)
    L.fam('inside', 'compositing', V(F, C3, C4), [i('in', '$T', 0), i('mask', F, 1)], o('$T', di='in'),
          'Multiply by a mask.')
    L.fam('outside', 'compositing', V(F, C3, C4), [i('in', '$T', 0), i('mask', F, 0)], o('$T', di='in'),
          'Multiply by the inverse of a mask.')
    mixv = [('_float', dict(T=F, S=F))]
    for t in [C3, C4, V2, V3, V4]:
        mixv += [('_' + t, dict(T=t, S=F)), ('_%s_%s' % (t, t), dict(T=t, S=t))]
    L.fam('mix', 'compositing', mixv, [i('fg', '$T', 0), i('bg', '$T', 0), i('mix', '$S', 0, **SOFT01)],
          o('$T', di='bg'), 'Linear blend: bg * (1 - mix) + fg * mix.')
    L.fam('mix', 'compositing', V(SS, DS, VS), [i('fg', '$T', ''), i('bg', '$T', ''), i('mix', F, 0, **SOFT01)],
          o('$T', di='bg'), 'Linear blend of two shaders.')

    # ---------------------------------------------------------------- conditional
    L.section('Conditionals and logic')
    cond_types = [F, I, C3, C4, V2, V3, V4, M3, M4]
    for node, v1, doc in [('ifgreater', 1, 'in1 if value1 > value2, else in2.'),
                          ('ifgreatereq', 1, 'in1 if value1 >= value2, else in2.'),
                          ('ifequal', 0, 'in1 if value1 == value2, else in2.')]:
        for suffix, ct in [('', F), ('I', I)] + ([('B', B)] if node == 'ifequal' else []):
            L.fam(node, 'conditional', [('_%s%s' % (t, suffix), dict(T=t)) for t in cond_types],
                  [i('value1', ct, v1), i('value2', ct, 0), i('in1', '$T', 0), i('in2', '$T', 0)],
                  o('$T', di='in1'), doc)
            L.fam(node, 'conditional', [('_boolean' + suffix, {})],
                  [i('value1', ct, 0 if ct == B else 1), i('value2', ct, 0)], o(B, False),
                  'Boolean result of the comparison.')
    for suffix, wt in [('', F), ('I', I)]:
        L.fam('switch', 'conditional', [('_%s%s' % (t, suffix), dict(T=t)) for t in [F, C3, C4, V2, V3, V4, M3, M4]],
              [i('in%d' % k, '$T', 0) for k in range(1, 11)] + [i('which', wt, 0)], o('$T', di='in1'),
              'Select one of ten inputs by index.')
    for node in ['and', 'or', 'xor']:
        L.fam(node, 'conditional', ONE, [i('in1', B, False), i('in2', B, False)], o(B, di='in1'),
              'Logical %s.' % node, name='ND_logical_' + node)
    L.fam('not', 'conditional', ONE, [i('in', B, False)], o(B, True), 'Logical not.', name='ND_logical_not')

    # ---------------------------------------------------------------- channel
    L.section('Channel operations')
    conversions = [(F, [C3, C4, V2, V3, V4]), (C3, [C4, V2, V3, V4]), (C4, [C3, V2, V3, V4]),
                   (V2, [C3, C4, V3, V4]), (V3, [C3, C4, V2, V4]), (V4, [C3, C4, V2, V3]),
                   (B, [F, C3, C4, V2, V3, V4, I]), (I, [F, C3, C4, V2, V3, V4, B])]
    for src, dsts in conversions:
        L.fam('convert', 'channel', [('_%s_%s' % (src, d), dict(T=d)) for d in dsts], [i('in', src, 0)],
              o('$T', 0), 'Convert between types (broadcast, truncate or pad).')
    L.fam('convert', 'shader', [('_%s_surfaceshader' % t, dict(T=t)) for t in [C3, C4, F, V2, V3, V4, I, B]],
          [i('in', '$T', 0)], o(SS), 'Display a value as an unlit surface shader.',
          version='1.0', isdefaultversion='true')
    L.fam('combine2', 'channel',
          [('_vector2', dict(T=V2, P=F, Q=F)), ('_color4CF', dict(T=C4, P=C3, Q=F)),
           ('_vector4VF', dict(T=V4, P=V3, Q=F)), ('_vector4VV', dict(T=V4, P=V2, Q=V2))],
          [i('in1', '$P', 0), i('in2', '$Q', 0)], o('$T', 0), 'Combine two values into a wider type.')
    L.fam('combine3', 'channel', V(C3, V3), [i('in%d' % k, F, 0) for k in (1, 2, 3)], o('$T', 0),
          'Combine three floats.')
    L.fam('combine4', 'channel', V(C4, V4), [i('in%d' % k, F, 0) for k in (1, 2, 3, 4)], o('$T', 0),
          'Combine four floats.')
    L.fam('creatematrix', 'math', [('_vector3_matrix33', {})],
          [i('in1', V3, (1, 0, 0)), i('in2', V3, (0, 1, 0)), i('in3', V3, (0, 0, 1))], o(M3, IDENT),
          'Build a matrix from row vectors.')
    L.fam('creatematrix', 'math', [('_vector3_matrix44', {})],
          [i('in1', V3, (1, 0, 0)), i('in2', V3, (0, 1, 0)), i('in3', V3, (0, 0, 1)), i('in4', V3, 0)],
          o(M4, IDENT), 'Build a matrix from row vectors (last column 0,0,0,1).')
    L.fam('creatematrix', 'math', [('_vector4_matrix44', {})],
          [i('in%d' % (k + 1), V4, tuple(1 if c == k else 0 for c in range(4))) for k in range(4)],
          o(M4, IDENT), 'Build a matrix from row vectors.')
    L.fam('extract', 'channel',
          [('_' + t, dict(T=t, R=F, X=n)) for t, n in [(C3, 2), (C4, 3), (V2, 1), (V3, 2), (V4, 3)]] +
          [('_matrix33', dict(T=M3, R=V3, X=2)), ('_matrix44', dict(T=M4, R=V4, X=3))],
          [i('in', '$T', 0), i('index', I, 0, u=True, uimin=0, uimax='$X')], o('$R', 0),
          'Extract one component (or one matrix row).')
    L.fam('separate2', 'channel', V(V2), [i('in', V2, 0)], [o(F, 0, name='out' + c) for c in 'xy'],
          'Split into components.')
    L.fam('separate3', 'channel', V(C3), [i('in', C3, 0)], [o(F, 0, name='out' + c) for c in 'rgb'],
          'Split into components.')
    L.fam('separate3', 'channel', V(V3), [i('in', V3, 0)], [o(F, 0, name='out' + c) for c in 'xyz'],
          'Split into components.')
    L.fam('separate4', 'channel', V(C4), [i('in', C4, 0)], [o(F, 0, name='out' + c) for c in 'rgba'],
          'Split into components.')
    L.fam('separate4', 'channel', V(V4), [i('in', V4, 0)], [o(F, 0, name='out' + c) for c in 'xyzw'],
          'Split into components.')

    # ---------------------------------------------------------------- convolution, organization
    L.section('Convolution')
    L.fam('blur', 'convolution2d', V(*NUM),
          [i('in', '$T', 0), i('size', F, 0), i('filtertype', STR, 'box', u=True, enum='box,gaussian')],
          o('$T', di='in'), 'Blur an upstream texture-space signal.')
    L.fam('heighttonormal', 'convolution2d', V(V3),
          [i('in', F, 0), i('scale', F, 1, uimin=0, uisoftmax=5), UV0], o(V3, (0.5, 0.5, 1)),
          'Derive a tangent-space normal from a height signal.')

    L.section('Organization')
    L.fam('dot', 'organization', V(F, C3, C4, V2, V3, V4, B, I, M3, M4, STR, FN, SS, DS, VS, LS),
          [i('in', '$T', I0), i('note', STR, '', u=True)], o('$T', di='in'),
          'Pass-through node for graph layout.')
    return L


# ==========================================================================
# pbrlib
# ==========================================================================

def build_pbrlib():
    L = Library(header('pbrlib (physically based BSDF/EDF/VDF nodes)', 'libraries/pbrlib/pbrlib_defs.mtlx'))
    L.section('Closure data types')
    L.elem('typedef', {'name': 'BSDF', 'doc': 'Scattering closure (reflection and/or transmission).'})
    L.elem('typedef', {'name': 'EDF', 'doc': 'Emission closure.'})
    L.elem('typedef', {'name': 'VDF', 'doc': 'Volume (participating medium) closure.'})

    W = i('weight', F, 1, **UNIT01)
    ROUGH2 = i('roughness', V2, 0.05)
    RETRO = i('retroreflective', B, False, u=True)
    FILM = [i('thinfilm_thickness', F, 0, unittype='distance', unit='nanometer'), i('thinfilm_ior', F, 1.5)]
    DIST = i('distribution', STR, 'ggx', u=True, enum='ggx')
    SCATTER = i('scatter_mode', STR, 'R', u=True, enum='R,T,RT')

    L.section('BSDFs')
    L.fam('oren_nayar_diffuse_bsdf', 'pbr', ONE,
          [W, i('color', C3, 0.18), i('roughness', F, 0), NWORLD, i('energy_compensation', B, False, u=True)],
          o('BSDF'), 'Oren-Nayar diffuse reflection.', bsdf='R')
    L.fam('burley_diffuse_bsdf', 'pbr', ONE, [W, i('color', C3, 0.18), i('roughness', F, 0), NWORLD],
          o('BSDF'), 'Burley (Disney) diffuse reflection.', bsdf='R')
    L.fam('translucent_bsdf', 'pbr', ONE, [W, i('color', C3, 1), NWORLD], o('BSDF'),
          'Diffuse transmission.', bsdf='R')
    L.fam('dielectric_bsdf', 'pbr', ONE,
          [W, i('tint', C3, 1), i('ior', F, 1.5), ROUGH2, RETRO] + FILM + [NWORLD, TWORLD, DIST, SCATTER],
          o('BSDF'), 'Microfacet dielectric reflection/transmission.')
    L.fam('conductor_bsdf', 'pbr', ONE,
          [W, i('ior', C3, (0.183, 0.421, 1.373)), i('extinction', C3, (3.424, 2.346, 1.770)), ROUGH2, RETRO] +
          FILM + [NWORLD, TWORLD, DIST],
          o('BSDF'), 'Microfacet conductor (metal) reflection.', bsdf='R')
    L.fam('generalized_schlick_bsdf', 'pbr', ONE,
          [W, i('color0', C3, 1), i('color82', C3, 1), i('color90', C3, 1), i('exponent', F, 5), ROUGH2, RETRO] +
          FILM + [NWORLD, TWORLD, DIST, SCATTER],
          o('BSDF'), 'Microfacet BSDF with artist-driven Schlick Fresnel.')
    L.fam('subsurface_bsdf', 'pbr', ONE,
          [W, i('color', C3, 0.18), i('radius', C3, 1), i('anisotropy', F, 0), NWORLD], o('BSDF'),
          'Subsurface scattering.', bsdf='R')
    L.fam('sheen_bsdf', 'pbr', ONE,
          [W, i('color', C3, 1), i('roughness', F, 0.3), NWORLD,
           i('mode', STR, 'conty_kulla', u=True, enum='conty_kulla,zeltner')],
          o('BSDF'), 'Sheen (cloth-like) reflection, layered over a base.', bsdf='R')
    L.fam('chiang_hair_bsdf', 'pbr', ONE,
          [i('tint_R', C3, 1), i('tint_TT', C3, 1), i('tint_TRT', C3, 1), i('ior', F, 1.55),
           i('roughness_R', V2, 0.1), i('roughness_TT', V2, 0.05), i('roughness_TRT', V2, 0.2),
           i('cuticle_angle', F, 0.5), i('absorption_coefficient', V3, 0), NWORLD,
           i('curve_direction', V3, g='Tworld')],
          o('BSDF'), 'Chiang hair scattering.', bsdf='R')

    L.section('EDFs')
    L.fam('uniform_edf', 'pbr', ONE, [i('color', C3, 1)], o('EDF'), 'Uniform (Lambertian) emission.')
    L.fam('conical_edf', 'pbr', ONE,
          [i('color', C3, 1), NWORLD, i('inner_angle', F, 60), i('outer_angle', F, 0)], o('EDF'),
          'Emission restricted to a cone.')
    L.fam('measured_edf', 'pbr', ONE, [i('color', C3, 1), NWORLD, i('file', FN, '', u=True)], o('EDF'),
          'Emission from a measured profile file.')
    L.fam('generalized_schlick_edf', 'pbr', ONE,
          [i('color0', C3, 1), i('color90', C3, 1), i('exponent', F, 5), i('base', 'EDF', '')], o('EDF'),
          'Modulate an EDF by a Schlick-style angular term.')

    L.section('VDFs')
    L.fam('absorption_vdf', 'pbr', ONE, [i('absorption', V3, 0)], o('VDF'), 'Absorbing medium.')
    L.fam('anisotropic_vdf', 'pbr', ONE,
          [i('absorption', V3, 0), i('scattering', V3, 0), i('anisotropy', F, 0)], o('VDF'),
          'Absorbing and scattering medium (Henyey-Greenstein).')

    L.section('Shader constructors')
    L.fam('surface', 'pbr', ONE,
          [i('bsdf', 'BSDF', ''), i('edf', 'EDF', ''), i('opacity', F, 1), i('thin_walled', B, False, u=True)],
          o(SS), 'Build a surface shader from closures.')
    L.fam('volume', 'pbr', ONE, [i('vdf', 'VDF', ''), i('edf', 'EDF', '')], o(VS),
          'Build a volume shader from closures.')
    L.fam('light', 'pbr', ONE, [i('edf', 'EDF', ''), i('intensity', F, 1), i('exposure', F, 0)], o(LS),
          'Build a light shader from an EDF.')
    L.fam('displacement', 'pbr', V(F, V3), [i('displacement', '$T', 0), i('scale', F, 1)], o(DS),
          'Scalar or vector displacement shader.')

    L.section('Closure combinators')
    L.fam('layer', 'pbr', [('_bsdf', dict(T='BSDF')), ('_vdf', dict(T='VDF'))],
          [i('top', 'BSDF', ''), i('base', '$T', '')], o('BSDF'), 'Layer a BSDF over a base.',
          defaultinput='top')
    cl = [('_bsdf', dict(T='BSDF')), ('_edf', dict(T='EDF')), ('_vdf', dict(T='VDF'))]
    L.fam('mix', 'pbr', cl, [i('fg', '$T', ''), i('bg', '$T', ''), i('mix', F, 0, **UNIT01)], o('$T'),
          'Weighted blend of two closures.', defaultinput='bg')
    L.fam('add', 'pbr', cl, [i('in1', '$T', ''), i('in2', '$T', '')], o('$T'), 'Sum of two closures.',
          defaultinput='bg')
    L.fam('multiply', 'pbr',
          [('_%s%s' % (c, s), dict(T=c.upper(), S=st)) for c in ('bsdf', 'edf', 'vdf') for s, st in (('C', C3), ('F', F))],
          [i('in1', '$T', ''), i('in2', '$S', 1)], o('$T'), 'Scale a closure.', defaultinput='in1')

    L.section('Utilities')
    L.fam('roughness_anisotropy', 'pbr', ONE, [i('roughness', F, 0), i('anisotropy', F, 0)], o(V2),
          'Anisotropic roughness pair from roughness and anisotropy.')
    L.fam('roughness_dual', 'pbr', ONE, [i('roughness', V2, 0)], o(V2), 'Roughness pair from two roughnesses.')
    L.fam('glossiness_anisotropy', 'pbr', ONE,
          [i('glossiness', F, 1, **UNIT01), i('anisotropy', F, 0, **UNIT01)], o(V2),
          'Anisotropic roughness pair from glossiness.')
    L.fam('blackbody', 'pbr', ONE, [i('temperature', F, 5000)], o(C3), 'Black-body color for a temperature in K.')
    L.fam('artistic_ior', 'pbr', ONE,
          [i('reflectivity', C3, (0.944, 0.776, 0.373), colorspace='lin_rec709'),
           i('edge_color', C3, (0.998, 0.981, 0.751), colorspace='lin_rec709')],
          [o(C3, name='ior'), o(C3, name='extinction')], 'Conductor IOR/extinction from artist colors.')
    L.fam('deon_hair_absorption_from_melanin', 'pbr', ONE,
          [i('melanin_concentration', F, 0.25), i('melanin_redness', F, 0.5),
           i('eumelanin_color', C3, (0.657704, 0.498077, 0.254107), colorspace='lin_rec709', uiadvanced='true'),
           i('pheomelanin_color', C3, (0.829444, 0.67032, 0.349938), colorspace='lin_rec709', uiadvanced='true')],
          o(V3, name='absorption'), 'Hair absorption from melanin amounts.')
    L.fam('chiang_hair_absorption_from_color', 'pbr', ONE,
          [i('color', C3, 1), i('azimuthal_roughness', F, 0.2)], o(V3, name='absorption'),
          'Hair absorption from a target color.')
    L.fam('chiang_hair_roughness', 'pbr', ONE,
          [i('longitudinal', F, 0.1), i('azimuthal', F, 0.2), i('scale_TT', F, 0.5, uiadvanced='true'),
           i('scale_TRT', F, 2, uiadvanced='true')],
          [o(V2, name='roughness_' + lobe) for lobe in ('R', 'TT', 'TRT')], 'Per-lobe hair roughness.')
    return L


# ==========================================================================
# cmlib, nprlib, lights
# ==========================================================================

def build_cmlib():
    L = Library(header('cmlib (built-in color space transforms)', 'libraries/cmlib/cmlib_defs.mtlx'))
    L.section('Transforms from a named color space to lin_rec709')
    for src in ['g18_rec709', 'g22_rec709', 'rec709_display', 'acescg', 'g22_ap1', 'srgb_texture',
                'lin_adobergb', 'adobergb', 'srgb_displayp3', 'lin_displayp3']:
        node = src + '_to_lin_rec709'
        L.fam(node, 'colortransform', [('_color3', dict(T=C3, Z=0)), ('_color4', dict(T=C4, Z=(0, 0, 0, 1)))],
              [i('in', '$T', '$Z')], o('$T'), 'Convert %s to lin_rec709.' % src)
    return L


def build_nprlib():
    L = Library(header('nprlib (view-dependent / non-photorealistic nodes)', 'libraries/nprlib/nprlib_defs.mtlx'))
    L.section('View-dependent geometric property')
    L.elem('geompropdef', {'name': 'Vworld', 'type': V3, 'geomprop': 'viewdirection', 'space': 'world'})
    L.section('Nodes')
    L.fam('viewdirection', 'npr', V(V3), [i('space', STR, 'world', u=True, enum='model,object,world')],
          o(V3, (0, 0, 1)), 'Direction from the eye to the shaded point.')
    L.fam('facingratio', 'npr', V(F),
          [i('viewdirection', V3, g='Vworld'), NWORLD, i('faceforward', B, True), i('invert', B, False)],
          o(F, 0), 'Cosine between view direction and normal.')
    L.fam('gooch_shade', 'npr', ONE,
          [i('warm_color', C3, (0.8, 0.8, 0.7)), i('cool_color', C3, (0.3, 0.3, 0.8)),
           i('specular_intensity', F, 1, **UNIT01), i('shininess', F, 64, uimin=1, uisoftmax=256),
           i('light_direction', V3, (1, -0.5, -0.5), uimin=-1, uimax=1)],
          o(C3), 'Warm/cool technical-illustration shading.', name='ND_gooch_shade')
    return L


def build_lights():
    L = Library(header('lights (light shaders used by hardware code generation)',
                       'libraries/lights/lights_defs.mtlx'))
    L.section('Light shaders')
    L.fam('point_light', 'light', ONE,
          [i('position', V3), i('color', C3), i('intensity', F), i('decay_rate', F, 2)], o(LS),
          'Point light.', name='ND_point_light')
    L.fam('directional_light', 'light', ONE, [i('direction', V3), i('color', C3), i('intensity', F)], o(LS),
          'Directional light.', name='ND_directional_light')
    L.fam('spot_light', 'light', ONE,
          [i('position', V3), i('direction', V3), i('color', C3), i('intensity', F), i('decay_rate', F, 2),
           i('inner_angle', F), i('outer_angle', F)], o(LS), 'Spot light.', name='ND_spot_light')
    return L


# ==========================================================================
# Surface shaders (bxdf)
# ==========================================================================

def ui_from_ranges(typ, rng, norm):
    """Map a spec range / norm pair to MaterialX UI limits.

    rng  '[a,b]', '[a,inf)', '(a,inf)', ...: hard limits -> uimin / uimax.
    norm '[c,d]' or None: the "typically useful" range -> uisoftmin / uisoftmax,
         emitted only where it differs from the hard limit.
    An exclusive lower bound is still emitted as uimin.
    """
    d = {}
    if not rng:
        return d
    lo, hi = rng[1:-1].split(',')
    if hi.strip() != 'inf':
        d['uimax'] = float(hi)
    d['uimin'] = float(lo)
    if norm:
        slo, shi = (float(x) for x in norm[1:-1].split(','))
        if slo != d['uimin']:
            d['uisoftmin'] = slo
        if shi != d.get('uimax'):
            d['uisoftmax'] = shi
    return {k: fmt(typ, v) for k, v in d.items()}


def surface_inputs(table):
    """table: list of (uifolder, rows); row = (name, type, default, range, norm, flags).

    flags: 'adv' -> uiadvanced, 'uniform', 'hint=<x>', 'geom=<geomprop>'."""
    out = []
    for folder, rows in table:
        for name, typ, default, rng, norm, flags in rows:
            attrs = {'name': name, 'type': typ}
            geom = None
            extra = {}
            for f in flags.split():
                if f == 'adv':
                    extra['uiadvanced'] = 'true'
                elif f == 'uniform':
                    extra['uniform'] = 'true'
                elif f.startswith('hint='):
                    extra['hint'] = f[5:]
                elif f.startswith('geom='):
                    geom = f[5:]
                else:
                    raise ValueError(f)
            if geom:
                attrs['defaultgeomprop'] = geom
            else:
                attrs['value'] = fmt(typ, default)
            attrs.update(extra)
            attrs.update(ui_from_ranges(typ, rng, norm))
            attrs['uifolder'] = folder
            out.append(('input', attrs))
    return out


# OpenPBR Surface 1.1.x: rows follow the "Parameter reference" table
# (parametrization.md.html): Range and Norm columns are copied as written
# there; the row order is the port order of the MaterialX nodedef.
OPENPBR = [
    ('Base', [
        ('base_weight', F, 1.0, '[0,1]', None, ''),
        ('base_color', C3, 0.8, '[0,1]', None, ''),
        ('base_diffuse_roughness', F, 0.0, '[0,1]', None, 'adv'),
        ('base_metalness', F, 0.0, '[0,1]', None, ''),
    ]),
    ('Specular', [
        ('specular_weight', F, 1.0, '[0,inf)', '[0,1]', ''),
        ('specular_color', C3, 1.0, '[0,1]', None, ''),
        ('specular_roughness', F, 0.3, '[0,1]', None, ''),
        ('specular_ior', F, 1.5, '(0,inf)', '[1,3]', ''),
        ('specular_roughness_anisotropy', F, 0.0, '[0,1]', None, 'adv'),
    ]),
    ('Transmission', [
        ('transmission_weight', F, 0.0, '[0,1]', None, 'adv hint=transparency'),
        ('transmission_color', C3, 1.0, '[0,1]', None, 'adv'),
        ('transmission_depth', F, 0.0, '[0,inf)', '[0,1]', 'adv'),
        ('transmission_scatter', C3, 0.0, '[0,1]', None, 'adv'),
        ('transmission_scatter_anisotropy', F, 0.0, '[-1,1]', None, 'adv'),
        ('transmission_dispersion_scale', F, 0.0, '[0,1]', None, 'adv'),
        ('transmission_dispersion_abbe_number', F, 20.0, '(0,inf)', '[9,91]', 'adv'),
    ]),
    ('Subsurface', [
        ('subsurface_weight', F, 0.0, '[0,1]', None, 'adv'),
        ('subsurface_color', C3, 0.8, '[0,1]', None, 'adv'),
        ('subsurface_radius', F, 1.0, '[0,inf)', '[0,1]', 'adv'),
        ('subsurface_radius_scale', C3, (1.0, 0.5, 0.25), '[0,1]', None, 'adv'),
        ('subsurface_scatter_anisotropy', F, 0.0, '[-1,1]', None, 'adv'),
    ]),
    ('Fuzz', [
        ('fuzz_weight', F, 0.0, '[0,1]', None, 'adv'),
        ('fuzz_color', C3, 1.0, '[0,1]', None, 'adv'),
        ('fuzz_roughness', F, 0.5, '[0,1]', None, 'adv'),
    ]),
    ('Coat', [
        ('coat_weight', F, 0.0, '[0,1]', None, ''),
        ('coat_color', C3, 1.0, '[0,1]', None, ''),
        ('coat_roughness', F, 0.0, '[0,1]', None, ''),
        ('coat_roughness_anisotropy', F, 0.0, '[0,1]', None, 'adv'),
        ('coat_ior', F, 1.6, '(0,inf)', '[1,3]', ''),
        ('coat_darkening', F, 1.0, '[0,1]', None, ''),
    ]),
    ('Thin Film', [
        ('thin_film_weight', F, 0.0, '[0,1]', None, 'adv'),
        ('thin_film_thickness', F, 0.5, '[0,inf)', '[0,1]', 'adv'),
        ('thin_film_ior', F, 1.4, '(0,inf)', '[1,3]', 'adv'),
    ]),
    ('Emission', [
        ('emission_luminance', F, 0.0, '[0,inf)', '[0,1000]', ''),
        ('emission_color', C3, 1.0, '[0,inf)', None, ''),
    ]),
    ('Geometry', [
        ('geometry_opacity', F, 1.0, '[0,1]', None, 'hint=opacity'),
        ('geometry_thin_walled', B, False, None, None, 'uniform adv'),
        ('geometry_normal', V3, None, None, None, 'geom=Nworld'),
        ('geometry_coat_normal', V3, None, None, None, 'geom=Nworld'),
        ('geometry_tangent', V3, None, None, None, 'geom=Tworld'),
        ('geometry_coat_tangent', V3, None, None, None, 'geom=Tworld'),
    ]),
]

# Autodesk Standard Surface 1.0.0 port list (defaults of spec version 1.0.0).
# Ranges stated in the spec are used as written; where the spec gives none the
# conventional UI limits of the shader are recorded in the same notation.
STANDARD_SURFACE = [
    ('Base', [
        ('base', F, 0.8, '[0,1]', None, ''),
        ('base_color', C3, 1.0, '[0,1]', None, ''),
        ('diffuse_roughness', F, 0.0, '[0,1]', None, 'adv'),
        ('metalness', F, 0.0, '[0,1]', None, ''),
    ]),
    ('Specular', [
        ('specular', F, 1.0, '[0,1]', None, ''),
        ('specular_color', C3, 1.0, '[0,1]', None, ''),
        ('specular_roughness', F, 0.2, '[0,1]', None, ''),
        ('specular_IOR', F, 1.5, '(0,inf)', '[1,3]', ''),
        ('specular_anisotropy', F, 0.0, '[0,1]', None, 'adv'),
        ('specular_rotation', F, 0.0, '[0,1]', None, 'adv'),
    ]),
    ('Transmission', [
        ('transmission', F, 0.0, '[0,1]', None, 'adv'),
        ('transmission_color', C3, 1.0, '[0,1]', None, 'adv'),
        ('transmission_depth', F, 0.0, '[0,inf)', '[0,100]', 'adv'),
        ('transmission_scatter', C3, 0.0, '[0,1]', None, 'adv'),
        ('transmission_scatter_anisotropy', F, 0.0, '[-1,1]', None, 'adv'),
        ('transmission_dispersion', F, 0.0, '[0,inf)', '[0,100]', 'adv'),
        ('transmission_extra_roughness', F, 0.0, '[-1,1]', '[0,1]', 'adv'),
    ]),
    ('Subsurface', [
        ('subsurface', F, 0.0, '[0,1]', None, 'adv'),
        ('subsurface_color', C3, 1.0, '[0,1]', None, 'adv'),
        ('subsurface_radius', C3, 1.0, '[0,1]', None, 'adv'),
        ('subsurface_scale', F, 1.0, '[0,inf)', '[0,10]', 'adv'),
        ('subsurface_anisotropy', F, 0.0, '[-1,1]', None, 'adv'),
    ]),
    ('Sheen', [
        ('sheen', F, 0.0, '[0,1]', None, 'adv'),
        ('sheen_color', C3, 1.0, '[0,1]', None, 'adv'),
        ('sheen_roughness', F, 0.3, '[0,1]', None, 'adv'),
    ]),
    ('Coat', [
        ('coat', F, 0.0, '[0,1]', None, ''),
        ('coat_color', C3, 1.0, '[0,1]', None, ''),
        ('coat_roughness', F, 0.1, '[0,1]', None, ''),
        ('coat_anisotropy', F, 0.0, '[0,1]', None, 'adv'),
        ('coat_rotation', F, 0.0, '[0,1]', None, 'adv'),
        ('coat_IOR', F, 1.5, '(0,inf)', '[1,3]', ''),
        ('coat_normal', V3, None, None, None, 'geom=Nworld'),
        ('coat_affect_color', F, 0.0, '[0,1]', None, 'adv'),
        ('coat_affect_roughness', F, 0.0, '[0,1]', None, 'adv'),
    ]),
    ('Thin Film', [
        ('thin_film_thickness', F, 0.0, '[0,inf)', '[0,2000]', 'adv'),
        ('thin_film_IOR', F, 1.5, '(0,inf)', '[1,3]', 'adv'),
    ]),
    ('Emission', [
        ('emission', F, 0.0, '[0,inf)', '[0,1]', ''),
        ('emission_color', C3, 1.0, '[0,1]', None, ''),
    ]),
    ('Geometry', [
        ('opacity', C3, 1.0, '[0,1]', None, ''),
        ('thin_walled', B, False, None, None, 'adv'),
        ('normal', V3, None, None, None, 'geom=Nworld'),
        ('tangent', V3, None, None, None, 'geom=Tworld'),
    ]),
]

# Version 1.0.1 only changes the base defaults (spec section "Metal": base 1, base_color 0.8).
STANDARD_SURFACE_101 = [('Base', [('base', F, 1.0, '[0,1]', None, ''), ('base_color', C3, 0.8, '[0,1]', None, '')])]


def build_standard_surface():
    L = Library(header(
        'Autodesk Standard Surface (nodedefs only)', 'libraries/bxdf/standard_surface.mtlx', [
            '',
            'No nodegraph: mxc lowers standard_surface to closures in C++.',
            'Source: Autodesk Standard Surface specification v1.0.1 (specification.md.html),',
            'sections "Shader parameters: transparency / coating / emission / metal / specular',
            'reflection / specular transmission / sheen / diffuse reflection / subsurface',
            'scattering" for port names, types and defaults, and the ranges stated there',
            '(e.g. [0,1] for anisotropy/rotation, [-1,1] for the scattering anisotropies,',
            '[0,infinity) for transmission_depth). Version 1.0.1 raises base to 1 and lowers',
            'base_color to 0.8 ("Metal" table); version 1.0.0 keeps 0.8 / 1 ("Diffuse reflection").']))
    L.section('Current version: overrides the base defaults and inherits everything else')
    L.elem('nodedef', {'name': 'ND_standard_surface_surfaceshader', 'node': 'standard_surface', 'nodegroup': 'pbr',
                       'version': '1.0.1', 'isdefaultversion': 'true',
                       'inherit': 'ND_standard_surface_surfaceshader_100',
                       'doc': 'Autodesk Standard Surface, version 1.0.1.'},
           surface_inputs(STANDARD_SURFACE_101))
    L.count += 1
    L.section('Version 1.0.0: full port list')
    L.elem('nodedef', {'name': 'ND_standard_surface_surfaceshader_100', 'node': 'standard_surface',
                       'nodegroup': 'pbr', 'version': '1.0.0',
                       'doc': 'Autodesk Standard Surface, version 1.0.0.'},
           surface_inputs(STANDARD_SURFACE) + [('output', {'name': 'out', 'type': SS})])
    L.count += 1
    return L


def build_open_pbr():
    L = Library(header(
        'OpenPBR Surface (nodedef only)', 'libraries/bxdf/open_pbr_surface.mtlx', [
            '',
            'No nodegraph: mxc lowers open_pbr_surface to closures in C++.',
            'Source: OpenPBR Surface specification v1.1.1, section "Parameter reference"',
            '(parametrization.md.html): identifiers, types and defaults as tabulated; the Range',
            'column gives uimin/uimax and the Norm column uisoftmin/uisoftmax. The per-lobe',
            'tables ("Base Substrate", "Thin-film iridescence", "Coat", "Fuzz", "Emission",',
            '"Opacity / Transparency", "Normal maps", "Thin-walled mode") describe each port.',
            'emission_color follows the 1.1.1 range [0, infinity) ("Emission" section).']))
    L.section('OpenPBR Surface')
    L.elem('nodedef', {'name': 'ND_open_pbr_surface_surfaceshader', 'node': 'open_pbr_surface',
                       'nodegroup': 'pbr', 'version': '1.1.1', 'isdefaultversion': 'true',
                       'doc': 'OpenPBR Surface uber-shader, version 1.1.1.'},
           surface_inputs(OPENPBR) + [('output', {'name': 'out', 'type': SS})])
    L.count += 1
    return L


def build_usd_preview_surface():
    L = Library(header(
        'UsdPreviewSurface and its texture nodes (nodedefs only)', 'libraries/bxdf/usd_preview_surface.mtlx', [
            '',
            'No nodegraph: mxc lowers UsdPreviewSurface to closures in C++',
            '(compiler/lower/UsdPreviewSurfaceLowering.cpp), and UsdUVTexture, UsdPrimvarReader',
            'and UsdTransform2d by rules (compiler/lower/StdlibRules.cpp).',
            'Source: the UsdPreviewSurface specification, version 2.6 (OpenUSD documentation,',
            '"UsdPreviewSurface Specification"), section "Preview Surface": input names, types',
            'and fallback values; opacityMode (2.6) is 0 for transparent, 1 for presence.']))
    L.section('UsdPreviewSurface')
    inputs = [
        i('diffuseColor', 'color3', '0.18, 0.18, 0.18'),
        i('emissiveColor', 'color3', '0, 0, 0'),
        i('useSpecularWorkflow', 'integer', '0', uimin='0', uimax='1'),
        i('specularColor', 'color3', '0, 0, 0'),
        i('metallic', 'float', '0', uimin='0.0', uimax='1.0'),
        i('roughness', 'float', '0.5', uimin='0.0', uimax='1.0'),
        i('clearcoat', 'float', '0', uimin='0.0', uimax='1.0'),
        i('clearcoatRoughness', 'float', '0.01', uimin='0.0', uimax='1.0'),
        i('opacity', 'float', '1', uimin='0.0', uimax='1.0'),
        i('opacityMode', 'integer', '0', enum='transparent,presence', enumvalues='0,1'),
        i('opacityThreshold', 'float', '0', uimin='0.0', uimax='1.0'),
        i('ior', 'float', '1.5'),
        i('normal', 'vector3', '0, 0, 1'),
        i('displacement', 'float', '0'),
        i('occlusion', 'float', '1', uimin='0.0', uimax='1.0'),
    ]
    L.elem('nodedef', {'name': 'ND_UsdPreviewSurface_surfaceshader', 'node': 'UsdPreviewSurface', 'nodegroup': 'pbr',
                       'version': '2.6', 'isdefaultversion': 'true',
                       'doc': 'UsdPreviewSurface, version 2.6.'},
           inputs + [('output', {'name': 'out', 'type': SS})])
    L.count += 1

    # The texture nodes of the UsdPreviewSurface specification ("Texture Reader", "Primvar
    # Reader", "Transform2d"), with MaterialX's names, inputs and defaults for them; lowered by
    # rules in compiler/lower/StdlibRules.cpp. MaterialX spells the wrap mode `repeat` as
    # `periodic`. Version 2.2 of UsdUVTexture also had an rgba output.
    def clean(ports):
        return [(tag, {k: v for k, v in attrs.items() if v is not None}) for tag, attrs in ports]

    L.section('UsdUVTexture')
    channels = [o(F, name='r'), o(F, name='g'), o(F, name='b'), o(F, name='a'), o(C3, name='rgb')]
    L.elem('nodedef', {'name': 'ND_UsdUVTexture', 'node': 'UsdUVTexture', 'nodegroup': 'texture2d', 'version': '2.2',
                       'inherit': 'ND_UsdUVTexture_23'},
           clean(channels + [o(C4, name='rgba')]))
    wrap = dict(enum='black,clamp,periodic,mirror')
    L.elem('nodedef', {'name': 'ND_UsdUVTexture_23', 'node': 'UsdUVTexture', 'nodegroup': 'texture2d', 'version': '2.3',
                       'isdefaultversion': 'true'},
           clean([i('file', FN, '', u=True), i('st', V2, None, g='UV0'),
            i('wrapS', STR, 'periodic', u=True, **wrap), i('wrapT', STR, 'periodic', u=True, **wrap),
            i('fallback', C4, '0, 0, 0, 1'), i('scale', C4, '1, 1, 1, 1', u=True), i('bias', C4, '0, 0, 0, 0', u=True)]
           + channels))
    L.count += 2
    L.section('UsdPrimvarReader')
    fallbacks = [(I, '0'), (B, 'false'), (STR, ''), (FN, ''), (F, '0'), (V2, '0, 0'), (V3, '0, 0, 0'),
                 (V4, '0, 0, 0, 0')]
    for typ, value in fallbacks:
        uniform = typ in (STR, FN)
        L.elem('nodedef', {'name': 'ND_UsdPrimvarReader_' + typ, 'node': 'UsdPrimvarReader', 'nodegroup': 'geometric'},
               clean([i('varname', STR, '', u=True), i('fallback', typ, value, u=uniform), o(typ, u=uniform)]))
        L.count += 1
    L.section('UsdTransform2d')
    L.elem('nodedef', {'name': 'ND_UsdTransform2d', 'node': 'UsdTransform2d', 'nodegroup': 'math'},
           clean([i('in', V2, '0, 0'), i('rotation', F, '0'), i('scale', V2, '1, 1'), i('translation', V2, '0, 0'), o(V2)]))
    L.count += 1
    return L


def build_gltf_pbr():
    L = Library(header(
        'glTF PBR (nodedef only)', 'libraries/bxdf/gltf_pbr.mtlx', [
            '',
            'No nodegraph: mxc lowers gltf_pbr to closures in C++ (compiler/lower/GltfPbrLowering.cpp).',
            'Source: the glTF 2.0 specification, "Metallic-Roughness Material" and Appendix B,',
            'and the Khronos extensions KHR_materials_specular, _ior, _transmission, _volume,',
            '_clearcoat, _sheen, _iridescence, _emissive_strength, _anisotropy and _dispersion:',
            'their factors, with the defaults the extensions give. attenuation_distance has no',
            'default: absent, the volume does not absorb (the extension\'s infinity).']))
    L.section('glTF PBR')
    inputs = [
        i('base_color', 'color3', '1, 1, 1', uimin='0, 0, 0', uimax='1, 1, 1'),
        i('metallic', 'float', '1', uimin='0', uimax='1'),
        i('roughness', 'float', '1', uimin='0', uimax='1'),
        i('normal', 'vector3', g='Nworld'),
        i('tangent', 'vector3', g='Tworld'),
        i('occlusion', 'float', '1', uimin='0', uimax='1'),
        i('transmission', 'float', '0', uimin='0', uimax='1'),
        i('specular', 'float', '1', uimin='0', uimax='1'),
        i('specular_color', 'color3', '1, 1, 1', uimin='0, 0, 0', uisoftmax='1, 1, 1'),
        i('ior', 'float', '1.5', u=True, uimin='1', uisoftmax='3'),
        i('alpha', 'float', '1', uimin='0', uimax='1'),
        i('alpha_mode', 'integer', '0', u=True, enum='OPAQUE, MASK, BLEND', enumvalues='0, 1, 2'),
        i('alpha_cutoff', 'float', '0.5', u=True, uimin='0', uimax='1'),
        i('iridescence', 'float', '0', uimin='0', uimax='1'),
        i('iridescence_ior', 'float', '1.3', u=True, uimin='1', uisoftmax='3'),
        i('iridescence_thickness', 'float', '100', uimin='0', uisoftmin='100', uisoftmax='400'),
        i('sheen_color', 'color3', '0, 0, 0', uimin='0, 0, 0', uimax='1, 1, 1'),
        i('sheen_roughness', 'float', '0', uimin='0', uimax='1'),
        i('clearcoat', 'float', '0', uimin='0', uimax='1'),
        i('clearcoat_roughness', 'float', '0', uimin='0', uimax='1'),
        i('clearcoat_normal', 'vector3', g='Nworld'),
        i('emissive', 'color3', '0, 0, 0', uimin='0, 0, 0', uimax='1, 1, 1'),
        i('emissive_strength', 'float', '1', u=True, uimin='0'),
        i('thickness', 'float', '0', uimin='0'),
        i('attenuation_distance', 'float', u=True, uimin='0'),
        i('attenuation_color', 'color3', '1, 1, 1', u=True, uimin='0, 0, 0', uimax='1, 1, 1'),
        i('anisotropy_strength', 'float', '0', uimin='0', uimax='1'),
        i('anisotropy_rotation', 'float', '0', uimin='0', uimax='6.283185'),
        i('dispersion', 'float', '0', uimin='0', uisoftmax='1.0'),
    ]
    inputs = [(tag, {k: v for k, v in attrs.items() if v is not None}) for tag, attrs in inputs]
    L.elem('nodedef', {'name': 'ND_gltf_pbr_surfaceshader', 'node': 'gltf_pbr', 'nodegroup': 'pbr',
                       'version': '2.0.1', 'isdefaultversion': 'true', 'doc': 'glTF PBR, version 2.0.1.'},
           inputs + [('output', {'name': 'out', 'type': SS})])
    L.count += 1

    # glTF's texture lookups (a texture with KHR_texture_transform's offset, rotation and scale;
    # lowered by rules in compiler/lower/StdlibRules.cpp). The placement inputs are MaterialX's:
    # the pivot (0, 1) turns glTF's top-left origin into MaterialX's bottom-left one.
    L.section('glTF texture lookups')

    def placement(order):
        return [
            i('texcoord', 'vector2', g='UV0'),
            i('pivot', 'vector2', '0, 1'),
            i('scale', 'vector2', '1, 1'),
            i('rotate', 'float', '0', unit='degree', unittype='angle', uimin='0', uimax='360'),
            i('offset', 'vector2', '0, 0'),
            i('operationorder', 'integer', order),
            i('uaddressmode', 'string', 'periodic', u=True, enum='constant,clamp,periodic,mirror'),
            i('vaddressmode', 'string', 'periodic', u=True, enum='constant,clamp,periodic,mirror'),
            i('filtertype', 'string', 'linear', u=True, enum='closest,linear,cubic'),
        ]

    def clean(inputs):
        return [(tag, {k: v for k, v in attrs.items() if v is not None}) for tag, attrs in inputs]

    zero = {'color3': '0, 0, 0', 'color4': '0, 0, 0, 0', 'float': '0', 'vector3': '0, 0, 0'}
    one = {'color3': '1,1,1', 'color4': '1,1,1,1', 'float': '1'}
    for typ in ('color3', 'color4', 'float', 'vector3'):
        inputs = [i('file', 'filename', '', u=True)]
        if typ in one:
            inputs.append(i('factor', typ, one[typ]))
        inputs.append(i('default', typ, zero[typ]))
        inputs += placement('1' if typ == 'color4' else '0')
        L.elem('nodedef', {'name': 'ND_gltf_image_%s_%s_1_0' % (typ, typ), 'node': 'gltf_image', 'version': '1.0',
                           'isdefaultversion': 'true', 'nodegroup': 'texture2d',
                           'doc': 'A glTF texture lookup times its factor.'},
               clean(inputs) + [('output', {'name': 'out', 'type': typ, 'value': zero[typ]})])
        L.count += 1
    inputs = [i('file', 'filename', '', u=True), i('default', 'color4', '0, 0, 0, 0')] + placement('1') + [
        i('color', 'color4', '1, 1, 1, 1'), i('geomcolor', 'color4', '1, 1, 1, 1')]
    L.elem('nodedef', {'name': 'ND_gltf_colorimage', 'node': 'gltf_colorimage', 'version': '1.0',
                       'isdefaultversion': 'true', 'nodegroup': 'texture2d',
                       'doc': 'glTF base colour: texture times colour factor times vertex colour.'},
           clean(inputs) + [('output', {'name': 'outcolor', 'type': 'color3', 'value': '0, 0, 0'}),
                            ('output', {'name': 'outa', 'type': 'float', 'value': '0'})])
    L.count += 1
    inputs = [i('file', 'filename', '', u=True), i('default', 'vector3', '0.5, 0.5, 1')] + placement('0')
    L.elem('nodedef', {'name': 'ND_gltf_normalmap_vector3_1_0', 'node': 'gltf_normalmap', 'version': '1.0',
                       'isdefaultversion': 'true', 'nodegroup': 'texture2d',
                       'doc': 'A glTF normal texture, as a world-space normal.'},
           clean(inputs) + [('output', {'name': 'out', 'type': 'vector3', 'value': '0, 0, 0'})])
    L.count += 1
    # KHR_materials_iridescence's thickness texture (its G channel between the two thicknesses);
    # MaterialX's definition has no operationorder and pivot (0, 0).
    inputs = [i('file', 'filename', '', u=True, uifolder='Image'), i('default', 'vector3', '0, 0, 0', uifolder='Image'),
              i('texcoord', 'vector2', g='UV0', uifolder='Image'), i('pivot', 'vector2', '0, 0', uifolder='Image'),
              i('scale', 'vector2', '1, 1', uifolder='Image'), i('rotate', 'float', '0', uifolder='Image'),
              i('offset', 'vector2', '0, 0', uifolder='Image'),
              i('uaddressmode', 'string', 'periodic', u=True, enum='constant,clamp,periodic,mirror', uifolder='Image'),
              i('vaddressmode', 'string', 'periodic', u=True, enum='constant,clamp,periodic,mirror', uifolder='Image'),
              i('filtertype', 'string', 'linear', u=True, enum='closest,linear,cubic', uifolder='Image'),
              i('thicknessMin', 'float', '100', uifolder='Thickness'), i('thicknessMax', 'float', '400', uifolder='Thickness')]
    L.elem('nodedef', {'name': 'ND_gltf_iridescence_thickness_float_1_0', 'node': 'gltf_iridescence_thickness',
                       'version': '1.0', 'isdefaultversion': 'true', 'nodegroup': 'texture2d',
                       'doc': 'glTF iridescence thickness: the texture\'s green channel between the two thicknesses.'},
           clean(inputs) + [('output', {'name': 'out', 'type': 'float', 'value': '0'})])
    L.count += 1
    # KHR_materials_anisotropy's texture: direction in red and green, strength in blue.
    inputs = [i('file', 'filename', '', u=True, uifolder='Image'), i('default', 'vector3', '1.0, 0.5, 1', uifolder='Image')]
    inputs += [(tag, dict(attrs, uifolder='Image')) for tag, attrs in placement('0')]
    inputs += [i('anisotropy_strength', 'float', '1', uimin='0', uimax='1', uifolder='Anisotropy'),
               i('anisotropy_rotation', 'float', '0', uimin='0', uimax='6.283185', uifolder='Anisotropy')]
    L.elem('nodedef', {'name': 'ND_gltf_anisotropy_image', 'node': 'gltf_anisotropy_image', 'version': '1.0',
                       'isdefaultversion': 'true', 'nodegroup': 'texture2d',
                       'doc': 'glTF anisotropy texture: strength and rotation of the anisotropy.'},
           clean(inputs) + [('output', {'name': 'anisotropy_strength_out', 'type': 'float', 'value': '0'}),
                            ('output', {'name': 'anisotropy_rotation_out', 'type': 'float', 'value': '0'})])
    L.count += 1
    return L


def build_disney_principled():
    L = Library(header(
        'Disney Principled (nodedef only)', 'libraries/bxdf/disney_principled.mtlx', [
            '',
            'No nodegraph: mxc lowers disney_principled to closures in C++',
            '(compiler/lower/DisneyPrincipledLowering.cpp).',
            'Source: Burley 2012, "Physically-Based Shading at Disney" (the BRDF\'s parameters) and',
            'Burley 2015, "Extending the Disney BRDF to a BSDF with Integrated Subsurface',
            'Scattering" (specTrans, ior, subsurface distance); names, types and defaults as',
            'MaterialX\'s definition, so its documents resolve unchanged.']))
    L.section('Disney Principled')
    inputs = [
        i('baseColor', 'color3', '0.16, 0.16, 0.16'),
        i('metallic', 'float', '0', uimin='0.0', uimax='1.0'),
        i('roughness', 'float', '0.5', uimin='0.0', uimax='1.0'),
        i('anisotropic', 'float', '0', uimin='0.0', uimax='1.0'),
        i('specular', 'float', '0.5', uimin='0.0', uimax='1.0'),
        i('specularTint', 'float', '0', uimin='0.0', uimax='1.0'),
        i('sheen', 'float', '0', uimin='0.0', uimax='1.0'),
        i('sheenTint', 'float', '0.5', uimin='0.0', uimax='1.0'),
        i('clearcoat', 'float', '0', uimin='0.0', uimax='1.0'),
        i('clearcoatGloss', 'float', '1', uimin='0.0', uimax='1.0'),
        i('specTrans', 'float', '0', uimin='0.0', uimax='1.0'),
        i('ior', 'float', '1.5', uisoftmin='1.0', uisoftmax='3.0'),
        i('subsurface', 'float', '0'),
        i('subsurfaceDistance', 'color3', '1, 1, 1'),
    ]
    inputs = [(tag, {k: v for k, v in attrs.items() if v is not None}) for tag, attrs in inputs]
    L.elem('nodedef', {'name': 'ND_disney_principled', 'node': 'disney_principled', 'nodegroup': 'pbr',
                       'doc': 'The Disney Principled BSDF (Burley 2012, 2015).'},
           inputs + [('output', {'name': 'out', 'type': SS})])
    L.count += 1
    return L


def build_lama():
    L = Library(header(
        'Pixar Lama (nodedefs only)', 'libraries/bxdf/lama/*.mtlx', [
            '',
            'No nodegraphs: mxc lowers the Lama nodes to closures in C++ (compiler/lower/LamaRules.cpp,',
            'which states each mapping). Names, types, defaults, enums and UI ranges as MaterialX\'s',
            'definitions (version 1.0, the default version), so its documents resolve unchanged.']))
    U = dict(uniform='true')
    FRESNEL = dict(enum='Artistic,Scientific', enumvalues='0,1', **U)
    R01 = dict(uimin='0.0', uimax='1.0')
    ANISO = dict(uimin='-1.0', uimax='1.0')
    ROT = dict(uisoftmin='0.0', uisoftmax='1.0')
    V10 = dict(version='1.0', isdefaultversion='true')

    def nd(name, node, out, doc, inputs):
        inputs = [(tag, {k: v for k, v in attrs.items() if v is not None}) for tag, attrs in inputs]
        attrs = {'name': name, 'node': node, 'nodegroup': 'pbr', 'doc': doc}
        attrs.update(V10)
        L.elem('nodedef', attrs, inputs + [('output', {'name': 'out', 'type': out})])
        L.count += 1

    interior = [
        i('absorptionColor', C3, '1.0, 1.0, 1.0', uifolder='Interior', doc='Transmittance reached at absorptionRadius.'),
        i('absorptionRadius', F, '1.0', uimin='0.0', uifolder='Interior', doc='Distance at which absorptionColor is reached.'),
        i('scatterColor', C3, '0.0, 0.0, 0.0', uifolder='Interior', doc='Single-scattering albedo of the interior.'),
        i('scatterAnisotropy', F, '0.0', uifolder='Interior', doc='Henyey-Greenstein g of the interior.', **ANISO),
    ]
    L.section('Lama BSDFs')
    nd('ND_lama_conductor', 'LamaConductor', 'BSDF', 'Lama conductor: GGX microfacets, complex Fresnel.', [
        i('tint', C3, '1, 1, 1', uifolder='Main'),
        i('fresnelMode', I, '0', uifolder='Main', **FRESNEL),
        i('IOR', V3, '0.180000007153,0.419999986887,1.37000000477', uifolder='Main'),
        i('extinction', V3, '3.42000007629,2.34999990463,1.76999998093', uifolder='Main'),
        i('reflectivity', C3, '0.9450, 0.7772, 0.3737', uifolder='Main'),
        i('edgeColor', C3, '0.7137, 0.7373, 0.4550', uifolder='Main'),
        i('roughness', F, '0.1', uifolder='Main', **R01),
        i('normal', V3, g='Nworld', uifolder='Main'),
        i('anisotropy', F, '0.0', uifolder='Anisotropy', **ANISO),
        i('anisotropyDirection', V3, g='Tworld', uifolder='Anisotropy'),
        i('anisotropyRotation', F, '0.0', uifolder='Anisotropy', **ROT),
    ])
    nd('ND_lama_dielectric', 'LamaDielectric', 'BSDF', 'Lama dielectric: one interface over its interior.', [
        i('reflectionTint', C3, '1.0, 1.0, 1.0', uifolder='Main'),
        i('transmissionTint', C3, '1.0, 1.0, 1.0', uifolder='Main'),
        i('fresnelMode', I, '0', uifolder='Main', **FRESNEL),
        i('IOR', F, '1.5', uimin='1.0', uimax='3.0', uifolder='Main'),
        i('reflectivity', F, '0.04', uimin='0.0', uimax='1.0', uisoftmin='0.0', uisoftmax='0.25', uifolder='Main'),
        i('roughness', F, '0.1', uifolder='Main', **R01),
        i('normal', V3, g='Nworld', uifolder='Main'),
        i('anisotropy', F, '0.0', uifolder='Anisotropy', **ANISO),
        i('direction', V3, g='Tworld', uifolder='Anisotropy'),
        i('rotation', F, '0.0', uifolder='Anisotropy', **ROT),
    ] + interior)
    nd('ND_lama_diffuse', 'LamaDiffuse', 'BSDF', 'Lama diffuse: Oren-Nayar, energy-compensated.', [
        i('color', C3, '0.18, 0.18, 0.18'),
        i('roughness', F, '0.0', **R01),
        i('normal', V3, g='Nworld'),
        i('energyCompensation', F, '1.0', uifolder='Advanced', **dict(R01, **U)),
    ])
    nd('ND_lama_generalized_schlick', 'LamaGeneralizedSchlick', 'BSDF',
       'Lama generalized Schlick: a Schlick Fresnel interface over its interior.', [
        i('reflectionTint', C3, '1.0, 1.0, 1.0', uifolder='Main'),
        i('transmissionTint', C3, '1.0, 1.0, 1.0', uifolder='Main'),
        i('fresnelMode', I, '0', uifolder='Main', **FRESNEL),
        i('IOR', V3, '1.5,1.5,1.5', uifolder='Main'),
        i('reflectivity', C3, '0.04, 0.04, 0.04', uifolder='Main'),
        i('reflectivity90', C3, '1.0, 1.0, 1.0', uifolder='Main'),
        i('reflectivityProfile', F, '0.2', uifolder='Main', **R01),
        i('roughness', F, '0.1', uifolder='Main', **R01),
        i('normal', V3, g='Nworld', uifolder='Main'),
        i('anisotropy', F, '-1.0', uifolder='Anisotropy', **ANISO),
        i('anisotropyDirection', V3, g='Tworld', uifolder='Anisotropy'),
        i('anisotropyRotation', F, '0.0', uifolder='Anisotropy', **ROT),
    ] + interior)
    nd('ND_lama_iridescence', 'LamaIridescence', 'BSDF', 'Lama iridescence: a thin film alone.', [
        i('roughness', F, '0.01', uifolder='Main', **R01),
        i('anisotropy', F, '0.0', uifolder='Anisotropy', **ANISO),
        i('anisotropyDirection', V3, g='Tworld', uifolder='Anisotropy'),
        i('anisotropyRotation', F, '0.0', uifolder='Anisotropy', **ROT),
        i('relativeFilmThickness', F, '0.5', uifolder='Main', **R01),
        i('minFilmThickness', F, '400.0', uimin='0.0', uisoftmin='0.0', uisoftmax='1000.0', uifolder='Main'),
        i('maxFilmThickness', F, '800.0', uimin='0.0', uisoftmin='0.0', uisoftmax='1000.0', uifolder='Main'),
        i('filmIOR', F, '1.3', uimin='0.0', uisoftmin='1.0', uisoftmax='3.0', uifolder='Main'),
    ])
    nd('ND_lama_sheen', 'LamaSheen', 'BSDF', 'Lama sheen.', [
        i('color', C3, '1, 1, 1', uifolder='Main'),
        i('roughness', F, '0.1', uifolder='Main', **R01),
        i('normal', V3, g='Nworld', uifolder='Main'),
    ])
    nd('ND_lama_sss', 'LamaSSS', 'BSDF', 'Lama subsurface scattering.', [
        i('color', C3, '0.18, 0.18, 0.18', uifolder='Main'),
        i('normal', V3, g='Nworld', uifolder='Main'),
        i('sssRadius', C3, '0.0, 0.0, 0.0', uifolder='SSS'),
        i('sssScale', F, '1.0', uimin='0.0', uifolder='SSS'),
        i('sssMode', I, '0', enum='Path-traced Davis,Path-traced exponential,Diffusion Burley,Diffusion Burley (mean free path)',
          enumvalues='0,1,2,3', uifolder='Main', **U),
        i('sssIOR', F, '1.0', uimin='1.0', uisoftmin='1.0', uisoftmax='2.0', uifolder='SSS'),
        i('sssAnisotropy', F, '0.0', uifolder='SSS', **R01),
        i('sssBleed', F, '0.0', uifolder='SSS', **R01),
        i('sssFollowTopology', F, '0.0', uifolder='SSS', **R01),
        i('sssSubset', STR, '', uifolder='SSS', **U),
        i('sssContinuationRays', I, '0', uifolder='SSS'),
        i('sssUnitLength', F, '0.00328', uifolder='SSS'),
        i('mode', I, '0', enum='Reflection,Transmission,Reflection(with direct illumination)', enumvalues='0,1,2',
          uifolder='Advanced', **U),
        i('albedoInversionMethod', I, '0', enum='Pixar,Chiang', enumvalues='0,1', uifolder='Advanced'),
    ])
    nd('ND_lama_translucent', 'LamaTranslucent', 'BSDF', 'Lama translucent: diffuse transmission.', [
        i('color', C3, '0.18, 0.18, 0.18'),
        i('roughness', F, '0.0', **R01),
        i('normal', V3, g='Nworld'),
        i('energyCompensation', F, '1.0', uifolder='Advanced', **dict(R01, **U)),
    ])
    L.section('Lama EDFs')
    nd('ND_lama_emission', 'LamaEmission', 'EDF', 'Lama emission: uniform.', [
        i('color', C3, '0.0, 0.0, 0.0', uifolder='Main'),
    ])
    L.section('Lama combinations')
    for kind in ('bsdf', 'edf'):
        T = kind.upper()
        nd('ND_lama_add_' + kind, 'LamaAdd', T, 'Lama add: weight1 material1 + weight2 material2.', [
            i('material1', T), i('material2', T),
            i('weight1', F, '1.0', **R01), i('weight2', F, '0.0', **R01)])
        nd('ND_lama_mix_' + kind, 'LamaMix', T, 'Lama mix: material2 over material1 by mix.', [
            i('material1', T), i('material2', T), i('mix', F, '0.0', **R01)])
    nd('ND_lama_layer_bsdf', 'LamaLayer', 'BSDF', 'Lama layer: materialTop over materialBase.', [
        i('materialTop', 'BSDF'), i('materialBase', 'BSDF'),
        i('topMix', F, '1.0', **R01), i('topThickness', F, '0.0', uimin='0.0')])
    nd('ND_lama_surface', 'LamaSurface', 'material', 'Lama surface: a front and a back material.', [
        i('materialFront', 'BSDF'), i('materialBack', 'BSDF'), i('presence', F, '1.0')])
    return L


# ==========================================================================

OUTPUTS = [
    ('stdlib/stdlib_defs.mtlx', build_stdlib),
    ('pbrlib/pbrlib_defs.mtlx', build_pbrlib),
    ('cmlib/cmlib_defs.mtlx', build_cmlib),
    ('nprlib/nprlib_defs.mtlx', build_nprlib),
    ('lights/lights_defs.mtlx', build_lights),
    ('bxdf/standard_surface.mtlx', build_standard_surface),
    ('bxdf/open_pbr_surface.mtlx', build_open_pbr),
    ('bxdf/usd_preview_surface.mtlx', build_usd_preview_surface),
    ('bxdf/gltf_pbr.mtlx', build_gltf_pbr),
    ('bxdf/disney_principled.mtlx', build_disney_principled),
    ('bxdf/lama.mtlx', build_lama),
]


def main():
    for rel, build in OUTPUTS:
        lib = build()
        path = os.path.join(NODEDEFS, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, 'w', encoding='utf-8', newline='\n') as f:
            f.write(render(lib))
        print('%-32s %4d nodedefs' % (rel, lib.count))
    return 0


if __name__ == '__main__':
    sys.exit(main())
