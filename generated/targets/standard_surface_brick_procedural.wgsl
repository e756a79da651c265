// ==== corpus/materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx: material M_BrickPattern, placements ====
// mxc_tables {"binding":0,"group":0,"samplerBinding":512}
// MxcView {"binding":1,"group":0}
// MxcParameters {"binding":2,"group":0}
// mxc_texture_0 {"binding":5,"group":0,"samplerBinding":517}
// mxc_texture_1 {"binding":6,"group":0,"samplerBinding":518}
// mxc_texture_2 {"binding":7,"group":0,"samplerBinding":519}
// mxc_texture_3 {"binding":8,"group":0,"samplerBinding":520}
// mxc_texture_4 {"binding":9,"group":0,"samplerBinding":521}
// mxc_texture_5 {"binding":10,"group":0,"samplerBinding":522}
// mxc_env_radiance {"binding":0,"group":1,"samplerBinding":512}
// MxcEnvDistribution {"binding":1,"group":1}
// ==== fragment (main) ====
struct MxcGeometry {
    P: vec3<f32>,
    Pobj: vec3<f32>,
    N: vec3<f32>,
    Nobj: vec3<f32>,
    T: vec3<f32>,
    Tobj: vec3<f32>,
    B: vec3<f32>,
    Bobj: vec3<f32>,
    uv: vec2<f32>,
    color: vec4<f32>,
    objectToWorld: mat4x4<f32>,
    frame: f32,
    time: f32,
}

struct MxcLobe {
    kind: i32,
    mode: i32,
    weight: vec3<f32>,
    N: vec3<f32>,
    T: vec3<f32>,
    alpha: vec2<f32>,
    eta: f32,
    c0_: vec3<f32>,
    c1_: vec3<f32>,
    c2_: vec3<f32>,
    p0_: f32,
    p1_: f32,
    film: vec3<f32>,
    tau: vec3<f32>,
    tauEta: f32,
}

struct MxcClosure {
    lobes: array<MxcLobe, 2>,
    count: i32,
    choice: array<f32, 2>,
    choiceTotal: f32,
    ms: array<vec3<f32>, 2>,
    emission: vec3<f32>,
    transparency: vec3<f32>,
}

struct MxcSample {
    wi: vec3<f32>,
    weight: vec3<f32>,
    pdf: f32,
    delta: bool,
    evaluate: bool,
    valid: bool,
}

struct MxcView {
    objectToWorld: mat4x4<f32>,
    normalToWorld: mat4x4<f32>,
    worldToClip: mat4x4<f32>,
    eye: vec4<f32>,
    jitter: vec4<f32>,
    lightVector: array<vec4<f32>, 8>,
    lightSpot: array<vec4<f32>, 8>,
    lightRadiance: array<vec4<f32>, 8>,
    counts: vec4<i32>,
    environment: vec4<f32>,
}

struct MxcParameters {
    missing_textures: u32,
    frame: f32,
    time: f32,
}

struct MxcLobeSample {
    wi: vec3<f32>,
    value: vec3<f32>,
    pdf: f32,
    delta: bool,
    valid: bool,
}

struct MxcEnvDistribution {
    mxc_env_size: vec4<u32>,
    mxc_env_cells: array<vec4<f32>>,
}

const MXC_ENVIRONMENT: i32 = -1i;
const MXC_LIGHT_COUNT: i32 = -1i;
const MXC_LIGHT_KINDS: i32 = -1i;

var<private> mxc_texture_footprint: f32;
var<private> vPosition_1: vec3<f32>;
var<private> vObjectPosition_1: vec3<f32>;
var<private> vNormal_1: vec3<f32>;
var<private> gl_FrontFacing_1: bool;
@group(0) @binding(1) 
var<uniform> mxc_view: MxcView;
var<private> vTangent_1: vec4<f32>;
var<private> vObjectNormal_1: vec3<f32>;
var<private> vObjectTangent_1: vec3<f32>;
var<private> vUv_1: vec2<f32>;
@group(0) @binding(2) 
var<storage, read_write> mxc_params: MxcParameters;
var<private> gl_FragCoord_1: vec4<f32>;
var<private> outColor: vec4<f32>;
@group(0) @binding(0) 
var mxc_tables_texture: texture_2d<f32>;
@group(0) @binding(512) 
var mxc_tables_sampler: sampler;
@group(0) @binding(5) 
var mxc_texture_0_texture: texture_2d<f32>;
@group(0) @binding(517) 
var mxc_texture_0_sampler: sampler;
@group(0) @binding(6) 
var mxc_texture_1_texture: texture_2d<f32>;
@group(0) @binding(518) 
var mxc_texture_1_sampler: sampler;
@group(0) @binding(7) 
var mxc_texture_2_texture: texture_2d<f32>;
@group(0) @binding(519) 
var mxc_texture_2_sampler: sampler;
@group(0) @binding(8) 
var mxc_texture_3_texture: texture_2d<f32>;
@group(0) @binding(520) 
var mxc_texture_3_sampler: sampler;
@group(0) @binding(9) 
var mxc_texture_4_texture: texture_2d<f32>;
@group(0) @binding(521) 
var mxc_texture_4_sampler: sampler;
@group(0) @binding(10) 
var mxc_texture_5_texture: texture_2d<f32>;
@group(0) @binding(522) 
var mxc_texture_5_sampler: sampler;
@group(1) @binding(0) 
var mxc_env_radiance_texture: texture_2d<f32>;
@group(1) @binding(512) 
var mxc_env_radiance_sampler: sampler;
@group(1) @binding(1) 
var<storage, read_write> unnamed: MxcEnvDistribution;

fn mxc_luminance_u0028_vf3_u003b(c: ptr<function, vec3<f32>>) -> f32 {
    let _e144 = (*c);
    return dot(_e144, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l: ptr<function, MxcLobe>) -> bool {
    return false;
}

fn mxc_mean_u0028_vf3_u003b(c_1: ptr<function, vec3<f32>>) -> f32 {
    let _e145 = (*c_1)[0u];
    let _e147 = (*c_1)[1u];
    let _e150 = (*c_1)[2u];
    return (((_e145 + _e147) + _e150) * 0.33333334f);
}

fn mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b(cosi: ptr<function, f32>, eta: ptr<function, f32>) -> f32 {
    var sin2t: f32;
    var cost: f32;
    var rs: f32;
    var rp: f32;

    let _e149 = (*eta);
    if (abs((_e149 - 1f)) < 0.000001f) {
        return 0f;
    }
    let _e153 = (*cosi);
    let _e154 = (*cosi);
    let _e157 = (*eta);
    let _e158 = (*eta);
    sin2t = ((1f - (_e153 * _e154)) / (_e157 * _e158));
    let _e161 = sin2t;
    if (_e161 >= 1f) {
        return 1f;
    }
    let _e163 = sin2t;
    cost = sqrt((1f - _e163));
    let _e166 = (*cosi);
    let _e167 = (*eta);
    let _e168 = cost;
    let _e171 = (*cosi);
    let _e172 = (*eta);
    let _e173 = cost;
    rs = ((_e166 - (_e167 * _e168)) / (_e171 + (_e172 * _e173)));
    let _e177 = (*eta);
    let _e178 = (*cosi);
    let _e180 = cost;
    let _e182 = (*eta);
    let _e183 = (*cosi);
    let _e185 = cost;
    rp = (((_e177 * _e178) - _e180) / ((_e182 * _e183) + _e185));
    let _e188 = rs;
    let _e189 = rs;
    let _e191 = rp;
    let _e192 = rp;
    return (0.5f * ((_e188 * _e189) + (_e191 * _e192)));
}

fn mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_1: ptr<function, MxcLobe>, above: ptr<function, bool>) -> f32 {
    var local: f32;

    let _e146 = (*above);
    if _e146 {
        let _e148 = (*l_1).eta;
        local = _e148;
    } else {
        let _e150 = (*l_1).eta;
        local = (1f / _e150);
    }
    let _e152 = local;
    return _e152;
}

fn mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b(l_2: ptr<function, MxcLobe>, cosh_: ptr<function, f32>, above_1: ptr<function, bool>) -> vec3<f32> {
    var f: vec3<f32>;
    var param: MxcLobe;
    var param_1: bool;
    var param_2: f32;
    var param_3: f32;

    f = vec3<f32>(1f, 1f, 1f);
    let _e152 = (*l_2).kind;
    if (_e152 == 1i) {
        let _e154 = (*l_2);
        param = _e154;
        let _e155 = (*above_1);
        param_1 = _e155;
        let _e156 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param), (&param_1));
        let _e157 = (*cosh_);
        param_2 = _e157;
        param_3 = _e156;
        let _e158 = mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b((&param_2), (&param_3));
        f = vec3(_e158);
    }
    let _e160 = f;
    return _e160;
}

fn mxc_rough_alpha_u0028_vf2_u003b(alpha: ptr<function, vec2<f32>>) -> vec2<f32> {
    let _e144 = (*alpha);
    return max(_e144, vec2<f32>(0.0001f, 0.0001f));
}

fn mxc_ggx_d_u0028_vf3_u003b_vf2_u003b(m: ptr<function, vec3<f32>>, alpha_1: ptr<function, vec2<f32>>) -> f32 {
    var param_4: vec2<f32>;
    var s: vec3<f32>;
    var d: f32;

    let _e149 = (*m)[2u];
    if (_e149 <= 0f) {
        return 0f;
    }
    let _e151 = (*alpha_1);
    param_4 = _e151;
    let _e152 = mxc_rough_alpha_u0028_vf2_u003b((&param_4));
    (*alpha_1) = _e152;
    let _e154 = (*m)[0u];
    let _e156 = (*alpha_1)[0u];
    let _e159 = (*m)[1u];
    let _e161 = (*alpha_1)[1u];
    let _e164 = (*m)[2u];
    s = vec3<f32>((_e154 / _e156), (_e159 / _e161), _e164);
    let _e166 = s;
    let _e167 = s;
    d = dot(_e166, _e167);
    let _e170 = (*alpha_1)[0u];
    let _e173 = (*alpha_1)[1u];
    let _e175 = d;
    let _e177 = d;
    return (1f / ((((3.1415927f * _e170) * _e173) * _e175) * _e177));
}

fn mxc_sqr_u0028_f1_u003b(x: ptr<function, f32>) -> f32 {
    let _e144 = (*x);
    let _e145 = (*x);
    return (_e144 * _e145);
}

fn mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b(v: ptr<function, vec3<f32>>, alpha_2: ptr<function, vec2<f32>>) -> f32 {
    var param_5: vec2<f32>;
    var z2_: f32;
    var a2_: f32;
    var param_6: f32;
    var param_7: f32;

    let _e150 = (*alpha_2);
    param_5 = _e150;
    let _e151 = mxc_rough_alpha_u0028_vf2_u003b((&param_5));
    (*alpha_2) = _e151;
    let _e153 = (*v)[2u];
    let _e155 = (*v)[2u];
    z2_ = (_e153 * _e155);
    let _e157 = z2_;
    if (_e157 <= 0f) {
        return 10000000000f;
    }
    let _e160 = (*alpha_2)[0u];
    let _e162 = (*v)[0u];
    param_6 = (_e160 * _e162);
    let _e164 = mxc_sqr_u0028_f1_u003b((&param_6));
    let _e166 = (*alpha_2)[1u];
    let _e168 = (*v)[1u];
    param_7 = (_e166 * _e168);
    let _e170 = mxc_sqr_u0028_f1_u003b((&param_7));
    let _e172 = z2_;
    a2_ = ((_e164 + _e170) / _e172);
    let _e174 = a2_;
    return (0.5f * (-1f + sqrt((1f + _e174))));
}

fn mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b(v_1: ptr<function, vec3<f32>>, alpha_3: ptr<function, vec2<f32>>) -> f32 {
    var param_8: vec3<f32>;
    var param_9: vec2<f32>;

    let _e147 = (*v_1);
    param_8 = _e147;
    let _e148 = (*alpha_3);
    param_9 = _e148;
    let _e149 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_8), (&param_9));
    return (1f / (1f + _e149));
}

fn mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo: ptr<function, vec3<f32>>, m_1: ptr<function, vec3<f32>>, alpha_4: ptr<function, vec2<f32>>) -> f32 {
    var param_10: vec3<f32>;
    var param_11: vec2<f32>;
    var param_12: vec3<f32>;
    var param_13: vec2<f32>;

    let _e151 = (*wo)[2u];
    if (_e151 <= 0f) {
        return 0f;
    }
    let _e153 = (*wo);
    param_10 = _e153;
    let _e154 = (*alpha_4);
    param_11 = _e154;
    let _e155 = mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b((&param_10), (&param_11));
    let _e156 = (*wo);
    let _e157 = (*m_1);
    let _e161 = (*m_1);
    param_12 = _e161;
    let _e162 = (*alpha_4);
    param_13 = _e162;
    let _e163 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_12), (&param_13));
    let _e166 = (*wo)[2u];
    return (((_e155 * max(dot(_e156, _e157), 0f)) * _e163) / _e166);
}

fn mxc_is_delta_u0028_vf2_u003b(alpha_5: ptr<function, vec2<f32>>) -> bool {
    let _e145 = (*alpha_5)[0u];
    let _e147 = (*alpha_5)[1u];
    return (max(_e145, _e147) < 0.0001f);
}

fn mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_3: ptr<function, MxcLobe>, wo_1: ptr<function, vec3<f32>>, wi: ptr<function, vec3<f32>>) -> f32 {
    var param_14: vec2<f32>;
    var above_2: bool;
    var o: vec3<f32>;
    var local_1: vec3<f32>;
    var i: vec3<f32>;
    var local_2: vec3<f32>;
    var h: vec3<f32>;
    var p: f32;
    var param_15: vec3<f32>;
    var param_16: vec3<f32>;
    var param_17: vec2<f32>;
    var fr: f32;
    var param_18: MxcLobe;
    var param_19: f32;
    var param_20: bool;
    var param_21: vec3<f32>;
    var param_22: MxcLobe;
    var local_3: f32;
    var phi_2528_: bool;
    var phi_2609_: bool;

    let _e165 = (*l_3).kind;
    switch _e165 {
        case 2, 3, 1: {
            let _e179 = (*l_3).alpha;
            param_14 = _e179;
            let _e180 = mxc_is_delta_u0028_vf2_u003b((&param_14));
            if _e180 {
                return 0f;
            }
            let _e182 = (*wo_1)[2u];
            above_2 = (_e182 > 0f);
            let _e184 = above_2;
            if _e184 {
                let _e185 = (*wo_1);
                local_1 = _e185;
            } else {
                let _e186 = (*wo_1);
                local_1 = -(_e186);
            }
            let _e188 = local_1;
            o = _e188;
            let _e189 = above_2;
            if _e189 {
                let _e190 = (*wi);
                local_2 = _e190;
            } else {
                let _e191 = (*wi);
                local_2 = -(_e191);
            }
            let _e193 = local_2;
            i = _e193;
            let _e195 = i[2u];
            if (_e195 > 0f) {
                let _e197 = o;
                let _e198 = i;
                h = normalize((_e197 + _e198));
                let _e201 = o;
                param_15 = _e201;
                let _e202 = h;
                param_16 = _e202;
                let _e204 = (*l_3).alpha;
                param_17 = _e204;
                let _e205 = mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_15), (&param_16), (&param_17));
                let _e206 = o;
                let _e207 = h;
                p = (_e205 / (4f * max(dot(_e206, _e207), 0.000001f)));
                let _e213 = (*l_3).kind;
                if (_e213 == 2i) {
                    let _e215 = p;
                    return _e215;
                }
                let _e217 = (*l_3).mode;
                if ((_e217 & 1i) == 0i) {
                    return 0f;
                }
                let _e220 = o;
                let _e221 = h;
                let _e224 = (*l_3);
                param_18 = _e224;
                param_19 = max(dot(_e220, _e221), 0f);
                let _e225 = above_2;
                param_20 = _e225;
                let _e226 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_18), (&param_19), (&param_20));
                param_21 = _e226;
                let _e227 = mxc_mean_u0028_vf3_u003b((&param_21));
                fr = _e227;
                let _e228 = p;
                let _e229 = (*l_3);
                param_22 = _e229;
                let _e230 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_22));
                phi_2609_ = _e230;
                if _e230 {
                    let _e232 = (*l_3).mode;
                    phi_2609_ = ((_e232 & 1i) != 0i);
                }
                let _e236 = phi_2609_;
                let _e237 = fr;
                return (_e228 * select(1f, _e237, _e236));
            }
            return 0f;
        }
        default: {
            let _e167 = (*wo_1)[2u];
            let _e168 = (_e167 > 0f);
            phi_2528_ = _e168;
            if _e168 {
                let _e170 = (*wi)[2u];
                phi_2528_ = (_e170 > 0f);
            }
            let _e173 = phi_2528_;
            if _e173 {
                let _e175 = (*wi)[2u];
                local_3 = (_e175 * 0.31830987f);
            } else {
                local_3 = 0f;
            }
            let _e177 = local_3;
            return _e177;
        }
    }
}

fn mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b(sigma: ptr<function, f32>, wo_2: ptr<function, vec3<f32>>, wi_1: ptr<function, vec3<f32>>) -> f32 {
    var a: f32;
    var s_1: f32;
    var t: f32;
    var local_4: f32;

    let _e150 = (*sigma);
    a = (1f / (1f + (0.2877934f * _e150)));
    let _e154 = (*wi_1);
    let _e155 = (*wo_2);
    let _e158 = (*wi_1)[2u];
    let _e160 = (*wo_2)[2u];
    s_1 = (dot(_e154, _e155) - (_e158 * _e160));
    let _e163 = s_1;
    if (_e163 > 0f) {
        let _e166 = (*wi_1)[2u];
        let _e168 = (*wo_2)[2u];
        local_4 = max(max(_e166, _e168), 0.000001f);
    } else {
        local_4 = 1f;
    }
    let _e171 = local_4;
    t = _e171;
    let _e172 = a;
    let _e173 = (*sigma);
    let _e174 = a;
    let _e176 = s_1;
    let _e178 = t;
    return ((_e172 + (((_e173 * _e174) * _e176) / _e178)) * 0.31830987f);
}

fn mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo_3: ptr<function, vec3<f32>>, wi_2: ptr<function, vec3<f32>>, alpha_6: ptr<function, vec2<f32>>) -> f32 {
    var param_23: vec3<f32>;
    var param_24: vec2<f32>;
    var param_25: vec3<f32>;
    var param_26: vec2<f32>;

    let _e150 = (*wo_3);
    param_23 = _e150;
    let _e151 = (*alpha_6);
    param_24 = _e151;
    let _e152 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_23), (&param_24));
    let _e154 = (*wi_2);
    param_25 = _e154;
    let _e155 = (*alpha_6);
    param_26 = _e155;
    let _e156 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_25), (&param_26));
    return (1f / ((1f + _e152) + _e156));
}

fn mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_4: ptr<function, MxcLobe>, wo_4: ptr<function, vec3<f32>>, wi_3: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_27: vec2<f32>;
    var h_1: vec3<f32>;
    var f_1: vec3<f32>;
    var param_28: MxcLobe;
    var param_29: f32;
    var param_30: bool;
    var param_31: vec3<f32>;
    var param_32: vec2<f32>;
    var param_33: vec3<f32>;
    var param_34: vec3<f32>;
    var param_35: vec2<f32>;
    var phi_1930_: bool;
    var phi_1937_: bool;

    let _e158 = (*wo_4)[2u];
    let _e159 = (_e158 <= 0f);
    phi_1930_ = _e159;
    if !(_e159) {
        let _e162 = (*wi_3)[2u];
        phi_1930_ = (_e162 <= 0f);
    }
    let _e165 = phi_1930_;
    phi_1937_ = _e165;
    if !(_e165) {
        let _e168 = (*l_4).alpha;
        param_27 = _e168;
        let _e169 = mxc_is_delta_u0028_vf2_u003b((&param_27));
        phi_1937_ = _e169;
    }
    let _e171 = phi_1937_;
    if _e171 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e172 = (*wo_4);
    let _e173 = (*wi_3);
    h_1 = normalize((_e172 + _e173));
    let _e176 = (*wo_4);
    let _e177 = h_1;
    let _e180 = (*l_4);
    param_28 = _e180;
    param_29 = max(dot(_e176, _e177), 0f);
    param_30 = true;
    let _e181 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_28), (&param_29), (&param_30));
    f_1 = _e181;
    let _e183 = (*l_4).kind;
    if (_e183 == 1i) {
        let _e186 = (*l_4).c0_;
        let _e187 = f_1;
        f_1 = (_e187 * _e186);
    }
    let _e189 = f_1;
    let _e190 = h_1;
    param_31 = _e190;
    let _e192 = (*l_4).alpha;
    param_32 = _e192;
    let _e193 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_31), (&param_32));
    let _e195 = (*wo_4);
    param_33 = _e195;
    let _e196 = (*wi_3);
    param_34 = _e196;
    let _e198 = (*l_4).alpha;
    param_35 = _e198;
    let _e199 = mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_33), (&param_34), (&param_35));
    let _e202 = (*wo_4)[2u];
    return (((_e189 * _e193) * _e199) / vec3((4f * _e202)));
}

fn mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_5: ptr<function, MxcLobe>, wo_5: ptr<function, vec3<f32>>, wi_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var m_2: MxcLobe;
    var param_36: MxcLobe;
    var param_37: vec3<f32>;
    var param_38: vec3<f32>;
    var param_39: MxcLobe;
    var param_40: vec3<f32>;
    var param_41: vec3<f32>;
    var param_42: MxcLobe;
    var param_43: vec3<f32>;
    var param_44: vec3<f32>;
    var local_5: vec3<f32>;
    var param_45: f32;
    var param_46: vec3<f32>;
    var param_47: vec3<f32>;
    var phi_2461_: bool;
    var phi_2476_: bool;

    let _e161 = (*l_5).kind;
    switch _e161 {
        case 1: {
            let _e163 = (*wo_5)[2u];
            let _e165 = (*wi_4)[2u];
            if ((_e163 * _e165) > 0f) {
                let _e169 = (*l_5).mode;
                if ((_e169 & 1i) == 0i) {
                    return vec3<f32>(0f, 0f, 0f);
                }
                let _e173 = (*wo_5)[2u];
                if (_e173 < 0f) {
                    let _e175 = (*l_5);
                    m_2 = _e175;
                    let _e177 = (*l_5).eta;
                    m_2.eta = (1f / _e177);
                    m_2.c0_ = vec3<f32>(1f, 1f, 1f);
                    let _e181 = (*wo_5);
                    let _e183 = (*wi_4);
                    let _e185 = m_2;
                    param_36 = _e185;
                    param_37 = -(_e181);
                    param_38 = -(_e183);
                    let _e186 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_36), (&param_37), (&param_38));
                    return _e186;
                }
                let _e187 = (*l_5);
                param_39 = _e187;
                let _e188 = (*wo_5);
                param_40 = _e188;
                let _e189 = (*wi_4);
                param_41 = _e189;
                let _e190 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_39), (&param_40), (&param_41));
                return _e190;
            }
            return vec3<f32>(0f, 0f, 0f);
        }
        case 3, 2: {
            let _e192 = (*l_5).kind;
            let _e193 = (_e192 == 3i);
            phi_2461_ = _e193;
            if _e193 {
                let _e195 = (*l_5).mode;
                phi_2461_ = ((_e195 & 1i) == 0i);
            }
            let _e199 = phi_2461_;
            if _e199 {
                return vec3<f32>(0f, 0f, 0f);
            }
            let _e200 = (*l_5);
            param_42 = _e200;
            let _e201 = (*wo_5);
            param_43 = _e201;
            let _e202 = (*wi_4);
            param_44 = _e202;
            let _e203 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_42), (&param_43), (&param_44));
            return _e203;
        }
        case 4: {
            let _e205 = (*wo_5)[2u];
            let _e206 = (_e205 > 0f);
            phi_2476_ = _e206;
            if _e206 {
                let _e208 = (*wi_4)[2u];
                phi_2476_ = (_e208 > 0f);
            }
            let _e211 = phi_2476_;
            if _e211 {
                let _e213 = (*l_5).c0_;
                let _e215 = (*l_5).p0_;
                param_45 = _e215;
                let _e216 = (*wo_5);
                param_46 = _e216;
                let _e217 = (*wi_4);
                param_47 = _e217;
                let _e218 = mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b((&param_45), (&param_46), (&param_47));
                let _e221 = (*wi_4)[2u];
                local_5 = ((_e213 * _e218) * _e221);
            } else {
                local_5 = vec3<f32>(0f, 0f, 0f);
            }
            let _e223 = local_5;
            return _e223;
        }
        default: {
            return vec3<f32>(0f, 0f, 0f);
        }
    }
}

fn mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b(l_6: ptr<function, MxcLobe>, mu: ptr<function, f32>) -> vec3<f32> {
    return vec3<f32>(1f, 1f, 1f);
}

fn mxc_to_local_u0028_mf33_u003b_vf3_u003b(frame: ptr<function, mat3x3<f32>>, v_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e145 = (*v_2);
    let _e147 = (*frame)[0];
    let _e149 = (*v_2);
    let _e151 = (*frame)[1];
    let _e153 = (*v_2);
    let _e155 = (*frame)[2];
    return vec3<f32>(dot(_e145, _e147), dot(_e149, _e151), dot(_e153, _e155));
}

fn mxc_frame_u0028_vf3_u003b_vf3_u003b(N: ptr<function, vec3<f32>>, T: ptr<function, vec3<f32>>) -> mat3x3<f32> {
    var t_1: vec3<f32>;
    var l2_: f32;
    var s_2: f32;
    var a_1: f32;
    var b: f32;

    let _e150 = (*T);
    let _e151 = (*N);
    let _e152 = (*N);
    let _e153 = (*T);
    t_1 = (_e150 - (_e151 * dot(_e152, _e153)));
    let _e157 = t_1;
    let _e158 = t_1;
    l2_ = dot(_e157, _e158);
    let _e160 = l2_;
    if !((_e160 > 0.000000000001f)) {
        let _e164 = (*N)[2u];
        s_2 = select(-1f, 1f, (_e164 >= 0f));
        let _e167 = s_2;
        let _e169 = (*N)[2u];
        a_1 = (-1f / (_e167 + _e169));
        let _e173 = (*N)[0u];
        let _e175 = (*N)[1u];
        let _e177 = a_1;
        b = ((_e173 * _e175) * _e177);
        let _e179 = s_2;
        let _e181 = (*N)[0u];
        let _e184 = (*N)[0u];
        let _e186 = a_1;
        let _e189 = s_2;
        let _e190 = b;
        let _e192 = s_2;
        let _e195 = (*N)[0u];
        t_1 = vec3<f32>((1f + (((_e179 * _e181) * _e184) * _e186)), (_e189 * _e190), (-(_e192) * _e195));
    } else {
        let _e198 = l2_;
        let _e200 = t_1;
        t_1 = (_e200 * inverseSqrt(_e198));
    }
    let _e202 = t_1;
    let _e203 = (*N);
    let _e204 = t_1;
    let _e205 = cross(_e203, _e204);
    let _e206 = (*N);
    return mat3x3<f32>(vec3<f32>(_e202.x, _e202.y, _e202.z), vec3<f32>(_e205.x, _e205.y, _e205.z), vec3<f32>(_e206.x, _e206.y, _e206.z));
}

fn mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b(c_2: ptr<function, MxcClosure>, wo_6: ptr<function, vec3<f32>>, wi_5: ptr<function, vec3<f32>>, wantPdf: ptr<function, bool>, pdf: ptr<function, f32>) -> vec3<f32> {
    var f_2: vec3<f32>;
    var p_1: f32;
    var k: i32;
    var l_7: MxcLobe;
    var frame_1: mat3x3<f32>;
    var param_48: vec3<f32>;
    var param_49: vec3<f32>;
    var o_1: vec3<f32>;
    var param_50: mat3x3<f32>;
    var param_51: vec3<f32>;
    var i_1: vec3<f32>;
    var param_52: mat3x3<f32>;
    var param_53: vec3<f32>;
    var param_54: MxcLobe;
    var param_55: f32;
    var param_56: MxcLobe;
    var param_57: vec3<f32>;
    var param_58: vec3<f32>;
    var param_59: MxcLobe;
    var param_60: vec3<f32>;
    var param_61: vec3<f32>;
    var local_6: f32;

    f_2 = vec3<f32>(0f, 0f, 0f);
    p_1 = 0f;
    k = 0i;
    loop {
        let _e170 = k;
        let _e172 = (*c_2).count;
        if (_e170 < _e172) {
            let _e174 = k;
            let _e177 = (*c_2).lobes[_e174];
            l_7 = _e177;
            let _e179 = l_7.weight;
            if all((_e179 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e183 = l_7.N;
            param_48 = _e183;
            let _e185 = l_7.T;
            param_49 = _e185;
            let _e186 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_48), (&param_49));
            frame_1 = _e186;
            let _e187 = frame_1;
            param_50 = _e187;
            let _e188 = (*wo_6);
            param_51 = _e188;
            let _e189 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_50), (&param_51));
            o_1 = _e189;
            let _e190 = frame_1;
            param_52 = _e190;
            let _e191 = (*wi_5);
            param_53 = _e191;
            let _e192 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_52), (&param_53));
            i_1 = _e192;
            let _e194 = l_7.weight;
            let _e195 = k;
            let _e198 = (*c_2).ms[_e195];
            let _e201 = i_1[2u];
            let _e203 = l_7;
            param_54 = _e203;
            param_55 = abs(_e201);
            let _e204 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_54), (&param_55));
            let _e206 = l_7;
            param_56 = _e206;
            let _e207 = o_1;
            param_57 = _e207;
            let _e208 = i_1;
            param_58 = _e208;
            let _e209 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_56), (&param_57), (&param_58));
            let _e211 = f_2;
            f_2 = (_e211 + (((_e194 * _e198) * _e204) * _e209));
            let _e213 = (*wantPdf);
            if _e213 {
                let _e214 = k;
                let _e217 = (*c_2).choice[_e214];
                let _e218 = l_7;
                param_59 = _e218;
                let _e219 = o_1;
                param_60 = _e219;
                let _e220 = i_1;
                param_61 = _e220;
                let _e221 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_59), (&param_60), (&param_61));
                let _e223 = p_1;
                p_1 = (_e223 + (_e217 * _e221));
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e225 = k;
            k = (_e225 + 1i);
        }
    }
    let _e228 = (*c_2).choiceTotal;
    if (_e228 > 0f) {
        let _e230 = p_1;
        let _e232 = (*c_2).choiceTotal;
        local_6 = (_e230 / _e232);
    } else {
        local_6 = 0f;
    }
    let _e234 = local_6;
    (*pdf) = _e234;
    let _e235 = f_2;
    return _e235;
}

fn mxc_env_to_world_u0028_vf3_u003b_f1_u003b(m_3: ptr<function, vec3<f32>>, angle: ptr<function, f32>) -> vec3<f32> {
    var c_3: f32;
    var s_3: f32;

    let _e147 = (*angle);
    c_3 = cos(_e147);
    let _e149 = (*angle);
    s_3 = sin(_e149);
    let _e151 = c_3;
    let _e153 = (*m_3)[0u];
    let _e155 = s_3;
    let _e157 = (*m_3)[2u];
    let _e161 = (*m_3)[1u];
    let _e162 = s_3;
    let _e165 = (*m_3)[0u];
    let _e167 = c_3;
    let _e169 = (*m_3)[2u];
    return vec3<f32>(((_e151 * _e153) + (_e155 * _e157)), _e161, ((-(_e162) * _e165) + (_e167 * _e169)));
}

fn mxc_safe_sqrt_u0028_f1_u003b(x_1: ptr<function, f32>) -> f32 {
    let _e144 = (*x_1);
    return sqrt(max(_e144, 0f));
}

fn mxc_env_sample_u0028_vf4_u003b_f1_u003b(u: ptr<function, vec4<f32>>, pdf_1: ptr<function, f32>) -> vec3<f32> {
    var size: vec2<u32>;
    var n: u32;
    var k_1: u32;
    var cell: vec4<f32>;
    var i_2: u32;
    var j: u32;
    var phi: f32;
    var y0_: f32;
    var y1_: f32;
    var y: f32;
    var r: f32;
    var param_62: f32;

    let _e158 = unnamed.mxc_env_size;
    size = max(_e158.xy, vec2<u32>(1u, 1u));
    let _e162 = size[0u];
    let _e164 = size[1u];
    n = (_e162 * _e164);
    let _e167 = (*u)[0u];
    let _e168 = n;
    let _e172 = n;
    k_1 = min(u32((_e167 * f32(_e168))), (_e172 - 1u));
    let _e175 = k_1;
    let _e178 = unnamed.mxc_env_cells[_e175];
    cell = _e178;
    let _e180 = (*u)[1u];
    let _e182 = cell[0u];
    if (_e180 >= _e182) {
        let _e185 = cell[1u];
        let _e187 = n;
        k_1 = min(bitcast<u32>(_e185), (_e187 - 1u));
    }
    let _e190 = k_1;
    let _e194 = unnamed.mxc_env_cells[_e190][2u];
    (*pdf_1) = _e194;
    let _e195 = k_1;
    let _e197 = size[0u];
    i_2 = (_e195 % _e197);
    let _e199 = k_1;
    let _e201 = size[0u];
    j = (_e199 / _e201);
    let _e203 = i_2;
    let _e206 = (*u)[2u];
    let _e209 = size[0u];
    phi = (6.2831855f * (((f32(_e203) + _e206) / f32(_e209)) - 0.5f));
    let _e214 = j;
    let _e218 = size[1u];
    y0_ = cos(((3.1415927f * f32(_e214)) / f32(_e218)));
    let _e222 = j;
    let _e227 = size[1u];
    y1_ = cos(((3.1415927f * f32((_e222 + 1u))) / f32(_e227)));
    let _e231 = y0_;
    let _e232 = y1_;
    let _e234 = (*u)[3u];
    y = mix(_e231, _e232, _e234);
    let _e236 = y;
    let _e237 = y;
    param_62 = (1f - (_e236 * _e237));
    let _e240 = mxc_safe_sqrt_u0028_f1_u003b((&param_62));
    r = _e240;
    let _e241 = r;
    let _e242 = phi;
    let _e245 = y;
    let _e246 = r;
    let _e248 = phi;
    return vec3<f32>((_e241 * sin(_e242)), _e245, (-(_e246) * cos(_e248)));
}

fn mxc_power_heuristic_u0028_f1_u003b_f1_u003b(a_2: ptr<function, f32>, b_1: ptr<function, f32>) -> f32 {
    var a2_1: f32;
    var b2_: f32;
    var local_7: f32;

    let _e148 = (*a_2);
    let _e149 = (*a_2);
    a2_1 = (_e148 * _e149);
    let _e151 = (*b_1);
    let _e152 = (*b_1);
    b2_ = (_e151 * _e152);
    let _e154 = a2_1;
    let _e155 = b2_;
    if ((_e154 + _e155) > 0f) {
        let _e158 = a2_1;
        let _e159 = a2_1;
        let _e160 = b2_;
        local_7 = (_e158 / (_e159 + _e160));
    } else {
        local_7 = 0f;
    }
    let _e163 = local_7;
    return _e163;
}

fn mxc_env_uv_u0028_vf3_u003b(d_1: ptr<function, vec3<f32>>) -> vec2<f32> {
    var u_1: f32;
    var local_8: f32;
    var v_3: f32;

    let _e148 = (*d_1)[0u];
    let _e151 = (*d_1)[2u];
    if ((abs(_e148) + abs(_e151)) > 0.000000000001f) {
        let _e156 = (*d_1)[0u];
        let _e158 = (*d_1)[2u];
        local_8 = (0.5f + (atan2(_e156, -(_e158)) * 0.15915494f));
    } else {
        local_8 = 0.5f;
    }
    let _e163 = local_8;
    u_1 = _e163;
    let _e164 = (*d_1);
    let _e168 = (*d_1)[1u];
    v_3 = (atan2(length(_e164.xz), _e168) * 0.31830987f);
    let _e171 = u_1;
    let _e172 = v_3;
    return vec2<f32>(_e171, _e172);
}

fn mxc_env_cell_u0028_vf3_u003b(d_2: ptr<function, vec3<f32>>) -> u32 {
    var uv: vec2<f32>;
    var param_63: vec3<f32>;
    var size_1: vec2<u32>;
    var i_3: u32;
    var j_1: u32;

    let _e149 = (*d_2);
    param_63 = _e149;
    let _e150 = mxc_env_uv_u0028_vf3_u003b((&param_63));
    uv = _e150;
    let _e152 = unnamed.mxc_env_size;
    size_1 = max(_e152.xy, vec2<u32>(1u, 1u));
    let _e156 = uv[0u];
    let _e159 = size_1[0u];
    let _e164 = size_1[0u];
    i_3 = min(u32((max(_e156, 0f) * f32(_e159))), (_e164 - 1u));
    let _e168 = uv[1u];
    let _e171 = size_1[1u];
    let _e176 = size_1[1u];
    j_1 = min(u32((max(_e168, 0f) * f32(_e171))), (_e176 - 1u));
    let _e179 = j_1;
    let _e181 = size_1[0u];
    let _e183 = i_3;
    return ((_e179 * _e181) + _e183);
}

fn mxc_env_pdf_u0028_vf3_u003b(d_3: ptr<function, vec3<f32>>) -> f32 {
    var param_64: vec3<f32>;

    let _e145 = (*d_3);
    param_64 = _e145;
    let _e146 = mxc_env_cell_u0028_vf3_u003b((&param_64));
    let _e150 = unnamed.mxc_env_cells[_e146][2u];
    return _e150;
}

fn mxc_env_to_map_u0028_vf3_u003b_f1_u003b(w: ptr<function, vec3<f32>>, angle_1: ptr<function, f32>) -> vec3<f32> {
    var c_4: f32;
    var s_4: f32;

    let _e147 = (*angle_1);
    c_4 = cos(_e147);
    let _e149 = (*angle_1);
    s_4 = sin(_e149);
    let _e151 = c_4;
    let _e153 = (*w)[0u];
    let _e155 = s_4;
    let _e157 = (*w)[2u];
    let _e161 = (*w)[1u];
    let _e162 = s_4;
    let _e164 = (*w)[0u];
    let _e166 = c_4;
    let _e168 = (*w)[2u];
    return vec3<f32>(((_e151 * _e153) - (_e155 * _e157)), _e161, ((_e162 * _e164) + (_e166 * _e168)));
}

fn mxc_env_lookup_u0028_vf3_u003b(d_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_65: vec3<f32>;

    let _e145 = (*d_4);
    param_65 = _e145;
    let _e146 = mxc_env_uv_u0028_vf3_u003b((&param_65));
    let _e147 = textureSampleLevel(mxc_env_radiance_texture, mxc_env_radiance_sampler, _e146, 0f);
    return _e147.xyz;
}

fn mxc_sky_u0028_vf3_u003b(d_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var y_1: f32;
    var horizon: vec3<f32>;
    var zenith: vec3<f32>;
    var ground: vec3<f32>;

    let _e149 = (*d_5)[1u];
    y_1 = clamp(_e149, -1f, 1f);
    horizon = vec3<f32>(1f, 0.96f, 0.9f);
    zenith = vec3<f32>(0.3f, 0.5f, 0.95f);
    ground = vec3<f32>(0.16f, 0.145f, 0.13f);
    let _e151 = y_1;
    if (_e151 >= 0f) {
        let _e153 = horizon;
        let _e154 = zenith;
        let _e155 = y_1;
        return mix(_e153, _e154, vec3(sqrt(_e155)));
    }
    let _e159 = horizon;
    let _e160 = ground;
    let _e161 = y_1;
    return mix(_e159, _e160, vec3(sqrt(-(_e161))));
}

fn mxc_environment_code_u0028_() -> i32 {
    var local_9: i32;

    if false {
        local_9 = MXC_ENVIRONMENT;
    } else {
        let _e146 = mxc_view.counts[1u];
        local_9 = _e146;
    }
    let _e147 = local_9;
    return _e147;
}

fn mxc_environment_u0028_vf3_u003b(d_6: ptr<function, vec3<f32>>) -> vec3<f32> {
    var code: i32;
    var param_66: vec3<f32>;
    var param_67: vec3<f32>;
    var param_68: f32;
    var param_69: vec3<f32>;

    let _e149 = mxc_environment_code_u0028_();
    code = _e149;
    let _e150 = code;
    if (_e150 == 1i) {
        let _e154 = mxc_view.environment[0u];
        return vec3(_e154);
    }
    let _e156 = code;
    if (_e156 == 2i) {
        let _e160 = mxc_view.environment[0u];
        let _e161 = (*d_6);
        param_66 = _e161;
        let _e162 = mxc_sky_u0028_vf3_u003b((&param_66));
        return (_e162 * _e160);
    }
    let _e164 = code;
    if (_e164 == 3i) {
        let _e168 = mxc_view.environment[0u];
        let _e169 = (*d_6);
        param_67 = _e169;
        let _e172 = mxc_view.environment[2u];
        param_68 = _e172;
        let _e173 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_67), (&param_68));
        param_69 = _e173;
        let _e174 = mxc_env_lookup_u0028_vf3_u003b((&param_69));
        return (_e174 * _e168);
    }
    return vec3<f32>(0f, 0f, 0f);
}

fn mxc_exit_direction_u0028_vf3_u003b_vf3_u003b(d_7: ptr<function, vec3<f32>>, t_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var axis: vec3<f32>;
    var s_5: f32;
    var c_5: f32;

    let _e148 = (*d_7);
    let _e149 = (*t_2);
    axis = cross(_e148, _e149);
    let _e151 = axis;
    s_5 = length(_e151);
    let _e153 = s_5;
    if (_e153 < 0.000001f) {
        let _e155 = (*t_2);
        return _e155;
    }
    let _e156 = s_5;
    let _e157 = axis;
    axis = (_e157 / vec3(_e156));
    let _e160 = (*d_7);
    let _e161 = (*t_2);
    c_5 = dot(_e160, _e161);
    let _e163 = (*t_2);
    let _e164 = c_5;
    let _e166 = axis;
    let _e167 = (*t_2);
    let _e169 = s_5;
    let _e172 = axis;
    let _e173 = axis;
    let _e174 = (*t_2);
    let _e177 = c_5;
    return (((_e163 * _e164) + (cross(_e166, _e167) * _e169)) + ((_e172 * dot(_e173, _e174)) * (1f - _e177)));
}

fn mxc_to_world_u0028_mf33_u003b_vf3_u003b(frame_2: ptr<function, mat3x3<f32>>, v_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e146 = (*frame_2)[0];
    let _e148 = (*v_4)[0u];
    let _e151 = (*frame_2)[1];
    let _e153 = (*v_4)[1u];
    let _e157 = (*frame_2)[2];
    let _e159 = (*v_4)[2u];
    return (((_e146 * _e148) + (_e151 * _e153)) + (_e157 * _e159));
}

fn mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b(wo_7: ptr<function, vec3<f32>>, alpha_7: ptr<function, vec2<f32>>, u_2: ptr<function, vec2<f32>>) -> vec3<f32> {
    var param_70: vec2<f32>;
    var vh: vec3<f32>;
    var lensq: f32;
    var t1_: vec3<f32>;
    var local_10: vec3<f32>;
    var t2_: vec3<f32>;
    var r_1: f32;
    var phi_1: f32;
    var p1_: f32;
    var p2_: f32;
    var s_6: f32;
    var param_71: f32;
    var nh: vec3<f32>;
    var param_72: f32;

    let _e160 = (*alpha_7);
    param_70 = _e160;
    let _e161 = mxc_rough_alpha_u0028_vf2_u003b((&param_70));
    (*alpha_7) = _e161;
    let _e163 = (*alpha_7)[0u];
    let _e165 = (*wo_7)[0u];
    let _e168 = (*alpha_7)[1u];
    let _e170 = (*wo_7)[1u];
    let _e173 = (*wo_7)[2u];
    vh = normalize(vec3<f32>((_e163 * _e165), (_e168 * _e170), _e173));
    let _e177 = vh[0u];
    let _e179 = vh[0u];
    let _e182 = vh[1u];
    let _e184 = vh[1u];
    lensq = ((_e177 * _e179) + (_e182 * _e184));
    let _e187 = lensq;
    if (_e187 > 0f) {
        let _e190 = vh[1u];
        let _e193 = vh[0u];
        let _e195 = lensq;
        local_10 = (vec3<f32>(-(_e190), _e193, 0f) * inverseSqrt(_e195));
    } else {
        local_10 = vec3<f32>(1f, 0f, 0f);
    }
    let _e198 = local_10;
    t1_ = _e198;
    let _e199 = vh;
    let _e200 = t1_;
    t2_ = cross(_e199, _e200);
    let _e203 = (*u_2)[0u];
    r_1 = sqrt(_e203);
    let _e206 = (*u_2)[1u];
    phi_1 = (6.2831855f * _e206);
    let _e208 = r_1;
    let _e209 = phi_1;
    p1_ = (_e208 * cos(_e209));
    let _e212 = r_1;
    let _e213 = phi_1;
    p2_ = (_e212 * sin(_e213));
    let _e217 = vh[2u];
    s_6 = (0.5f * (1f + _e217));
    let _e220 = s_6;
    let _e222 = p1_;
    let _e223 = p1_;
    param_71 = (1f - (_e222 * _e223));
    let _e226 = mxc_safe_sqrt_u0028_f1_u003b((&param_71));
    let _e228 = s_6;
    let _e229 = p2_;
    p2_ = (((1f - _e220) * _e226) + (_e228 * _e229));
    let _e232 = p1_;
    let _e233 = t1_;
    let _e235 = p2_;
    let _e236 = t2_;
    let _e239 = p1_;
    let _e240 = p1_;
    let _e243 = p2_;
    let _e244 = p2_;
    param_72 = ((1f - (_e239 * _e240)) - (_e243 * _e244));
    let _e247 = mxc_safe_sqrt_u0028_f1_u003b((&param_72));
    let _e248 = vh;
    nh = (((_e233 * _e232) + (_e236 * _e235)) + (_e248 * _e247));
    let _e252 = (*alpha_7)[0u];
    let _e254 = nh[0u];
    let _e257 = (*alpha_7)[1u];
    let _e259 = nh[1u];
    let _e262 = nh[2u];
    return normalize(vec3<f32>((_e252 * _e254), (_e257 * _e259), max(_e262, 0f)));
}

fn mxc_sample_cosine_u0028_vf2_u003b(u_3: ptr<function, vec2<f32>>) -> vec3<f32> {
    var r_2: f32;
    var phi_2: f32;
    var param_73: f32;

    let _e148 = (*u_3)[0u];
    r_2 = sqrt(_e148);
    let _e151 = (*u_3)[1u];
    phi_2 = (6.2831855f * _e151);
    let _e153 = r_2;
    let _e154 = phi_2;
    let _e157 = r_2;
    let _e158 = phi_2;
    let _e162 = (*u_3)[0u];
    param_73 = (1f - _e162);
    let _e164 = mxc_safe_sqrt_u0028_f1_u003b((&param_73));
    return vec3<f32>((_e153 * cos(_e154)), (_e157 * sin(_e158)), _e164);
}

fn mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_8: ptr<function, MxcLobe>, wo_8: ptr<function, vec3<f32>>, u_4: ptr<function, vec3<f32>>) -> MxcLobeSample {
    var s_7: MxcLobeSample;
    var above_3: bool;
    var o_2: vec3<f32>;
    var local_11: vec3<f32>;
    var delta: bool;
    var param_74: vec2<f32>;
    var m_4: vec3<f32>;
    var local_12: vec3<f32>;
    var param_75: vec3<f32>;
    var param_76: vec2<f32>;
    var param_77: vec2<f32>;
    var hm: f32;
    var transmits: bool;
    var param_78: MxcLobe;
    var reflects: bool;
    var f_3: vec3<f32>;
    var param_79: MxcLobe;
    var param_80: f32;
    var param_81: bool;
    var fr_1: f32;
    var local_13: f32;
    var param_82: vec3<f32>;
    var pReflect: f32;
    var local_14: f32;
    var i_4: vec3<f32>;
    var local_15: vec3<f32>;
    var tint: vec3<f32>;
    var local_16: vec3<f32>;
    var local_17: vec3<f32>;
    var param_83: MxcLobe;
    var param_84: vec3<f32>;
    var param_85: vec3<f32>;
    var param_86: MxcLobe;
    var param_87: vec3<f32>;
    var param_88: vec3<f32>;
    var param_89: vec2<f32>;
    var param_90: MxcLobe;
    var param_91: vec3<f32>;
    var param_92: vec3<f32>;
    var param_93: MxcLobe;
    var param_94: vec3<f32>;
    var param_95: vec3<f32>;
    var phi_2740_: bool;
    var phi_2745_: bool;
    var phi_2756_: bool;

    s_7.valid = false;
    s_7.delta = false;
    s_7.pdf = 0f;
    s_7.value = vec3<f32>(0f, 0f, 0f);
    s_7.wi = vec3<f32>(0f, 0f, 1f);
    let _e194 = (*l_8).kind;
    switch _e194 {
        case 2, 3, 1: {
            let _e221 = (*wo_8)[2u];
            above_3 = (_e221 > 0f);
            let _e223 = above_3;
            if _e223 {
                let _e224 = (*wo_8);
                local_11 = _e224;
            } else {
                let _e225 = (*wo_8);
                local_11 = -(_e225);
            }
            let _e227 = local_11;
            o_2 = _e227;
            let _e229 = o_2[2u];
            if (_e229 <= 0f) {
                let _e231 = s_7;
                return _e231;
            }
            let _e233 = (*l_8).alpha;
            param_74 = _e233;
            let _e234 = mxc_is_delta_u0028_vf2_u003b((&param_74));
            delta = _e234;
            let _e235 = delta;
            if _e235 {
                local_12 = vec3<f32>(0f, 0f, 1f);
            } else {
                let _e236 = o_2;
                param_75 = _e236;
                let _e238 = (*l_8).alpha;
                param_76 = _e238;
                let _e239 = (*u_4);
                param_77 = _e239.xy;
                let _e241 = mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b((&param_75), (&param_76), (&param_77));
                local_12 = _e241;
            }
            let _e242 = local_12;
            m_4 = _e242;
            let _e243 = o_2;
            let _e244 = m_4;
            hm = dot(_e243, _e244);
            let _e247 = (*l_8).kind;
            let _e248 = (_e247 == 1i);
            phi_2740_ = _e248;
            if !(_e248) {
                let _e251 = (*l_8).kind;
                phi_2740_ = (_e251 == 3i);
            }
            let _e254 = phi_2740_;
            phi_2745_ = _e254;
            if _e254 {
                let _e255 = (*l_8);
                param_78 = _e255;
                let _e256 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_78));
                phi_2745_ = _e256;
            }
            let _e258 = phi_2745_;
            transmits = _e258;
            let _e260 = (*l_8).kind;
            let _e261 = (_e260 == 2i);
            phi_2756_ = _e261;
            if !(_e261) {
                let _e264 = (*l_8).mode;
                phi_2756_ = ((_e264 & 1i) != 0i);
            }
            let _e268 = phi_2756_;
            reflects = _e268;
            let _e269 = hm;
            let _e271 = (*l_8);
            param_79 = _e271;
            param_80 = max(_e269, 0f);
            let _e272 = above_3;
            param_81 = _e272;
            let _e273 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_79), (&param_80), (&param_81));
            f_3 = _e273;
            let _e274 = transmits;
            if _e274 {
                let _e275 = f_3;
                param_82 = _e275;
                let _e276 = mxc_mean_u0028_vf3_u003b((&param_82));
                local_13 = _e276;
            } else {
                local_13 = 1f;
            }
            let _e277 = local_13;
            fr_1 = _e277;
            let _e278 = transmits;
            if _e278 {
                let _e279 = reflects;
                let _e280 = fr_1;
                local_14 = select(0f, _e280, _e279);
            } else {
                local_14 = 1f;
            }
            let _e282 = local_14;
            pReflect = _e282;
            let _e284 = (*u_4)[2u];
            let _e285 = pReflect;
            if (_e284 < _e285) {
                let _e287 = o_2;
                let _e289 = m_4;
                i_4 = reflect(-(_e287), _e289);
                let _e292 = i_4[2u];
                if (_e292 <= 0f) {
                    let _e294 = s_7;
                    return _e294;
                }
                let _e295 = above_3;
                if _e295 {
                    let _e296 = i_4;
                    local_15 = _e296;
                } else {
                    let _e297 = i_4;
                    local_15 = -(_e297);
                }
                let _e299 = local_15;
                s_7.wi = _e299;
                let _e301 = delta;
                s_7.delta = _e301;
                let _e303 = delta;
                if _e303 {
                    let _e305 = (*l_8).kind;
                    if (_e305 == 1i) {
                        let _e307 = above_3;
                        if _e307 {
                            let _e309 = (*l_8).c0_;
                            local_17 = _e309;
                        } else {
                            local_17 = vec3<f32>(1f, 1f, 1f);
                        }
                        let _e310 = local_17;
                        local_16 = _e310;
                    } else {
                        local_16 = vec3<f32>(1f, 1f, 1f);
                    }
                    let _e311 = local_16;
                    tint = _e311;
                    let _e312 = f_3;
                    let _e313 = tint;
                    s_7.value = (_e312 * _e313);
                    let _e316 = pReflect;
                    s_7.pdf = _e316;
                } else {
                    let _e318 = (*l_8);
                    param_83 = _e318;
                    let _e319 = (*wo_8);
                    param_84 = _e319;
                    let _e321 = s_7.wi;
                    param_85 = _e321;
                    let _e322 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_83), (&param_84), (&param_85));
                    s_7.value = _e322;
                    let _e324 = (*l_8);
                    param_86 = _e324;
                    let _e325 = (*wo_8);
                    param_87 = _e325;
                    let _e327 = s_7.wi;
                    param_88 = _e327;
                    let _e328 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_86), (&param_87), (&param_88));
                    s_7.pdf = _e328;
                }
                let _e331 = s_7.pdf;
                s_7.valid = (_e331 > 0f);
                let _e334 = s_7;
                return _e334;
            }
            let _e335 = s_7;
            return _e335;
        }
        default: {
            let _e196 = (*wo_8)[2u];
            if (_e196 <= 0f) {
                let _e198 = s_7;
                return _e198;
            }
            let _e199 = (*u_4);
            param_89 = _e199.xy;
            let _e201 = mxc_sample_cosine_u0028_vf2_u003b((&param_89));
            s_7.wi = _e201;
            let _e203 = (*l_8);
            param_90 = _e203;
            let _e204 = (*wo_8);
            param_91 = _e204;
            let _e206 = s_7.wi;
            param_92 = _e206;
            let _e207 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_90), (&param_91), (&param_92));
            s_7.value = _e207;
            let _e209 = (*l_8);
            param_93 = _e209;
            let _e210 = (*wo_8);
            param_94 = _e210;
            let _e212 = s_7.wi;
            param_95 = _e212;
            let _e213 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_93), (&param_94), (&param_95));
            s_7.pdf = _e213;
            let _e216 = s_7.pdf;
            s_7.valid = (_e216 > 0f);
            let _e219 = s_7;
            return _e219;
        }
    }
}

fn mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b(c_6: ptr<function, MxcClosure>, wo_9: ptr<function, vec3<f32>>, u_5: ptr<function, vec3<f32>>) -> MxcSample {
    var s_8: MxcSample;
    var total: f32;
    var x_2: f32;
    var chosen: i32;
    var before: f32;
    var p_2: f32;
    var lastBefore: f32;
    var last: i32;
    var k_2: i32;
    var pk: f32;
    var uz: f32;
    var l_9: MxcLobe;
    var frame_3: mat3x3<f32>;
    var param_96: vec3<f32>;
    var param_97: vec3<f32>;
    var o_3: vec3<f32>;
    var param_98: mat3x3<f32>;
    var param_99: vec3<f32>;
    var ls: MxcLobeSample;
    var param_100: MxcLobe;
    var param_101: vec3<f32>;
    var param_102: vec3<f32>;
    var param_103: mat3x3<f32>;
    var param_104: vec3<f32>;
    var param_105: MxcLobe;
    var param_106: f32;

    s_8.valid = false;
    s_8.delta = false;
    s_8.evaluate = false;
    s_8.pdf = 0f;
    s_8.weight = vec3<f32>(0f, 0f, 0f);
    let _e177 = (*wo_9);
    s_8.wi = _e177;
    let _e180 = (*c_6).choiceTotal;
    total = _e180;
    let _e182 = (*c_6).count;
    let _e184 = total;
    if ((_e182 == 0i) || (_e184 <= 0f)) {
        let _e187 = s_8;
        return _e187;
    }
    let _e189 = (*u_5)[2u];
    let _e190 = total;
    x_2 = (_e189 * _e190);
    chosen = -1i;
    before = 0f;
    p_2 = 0f;
    lastBefore = 0f;
    last = -1i;
    k_2 = 0i;
    loop {
        let _e192 = k_2;
        let _e194 = (*c_6).count;
        if (_e192 < _e194) {
            let _e196 = k_2;
            let _e199 = (*c_6).choice[_e196];
            pk = _e199;
            let _e200 = pk;
            if (_e200 <= 0f) {
                continue;
            }
            let _e202 = x_2;
            let _e203 = before;
            let _e204 = pk;
            if (_e202 < (_e203 + _e204)) {
                let _e207 = k_2;
                chosen = _e207;
                let _e208 = pk;
                p_2 = _e208;
                break;
            }
            let _e209 = k_2;
            last = _e209;
            let _e210 = before;
            lastBefore = _e210;
            let _e211 = pk;
            let _e212 = before;
            before = (_e212 + _e211);
            continue;
        } else {
            break;
        }
        continuing {
            let _e214 = k_2;
            k_2 = (_e214 + 1i);
        }
    }
    let _e216 = chosen;
    if (_e216 < 0i) {
        let _e218 = last;
        chosen = max(_e218, 0i);
        let _e220 = chosen;
        let _e223 = (*c_6).choice[_e220];
        p_2 = _e223;
        let _e224 = lastBefore;
        before = _e224;
    }
    let _e225 = p_2;
    if (_e225 <= 0f) {
        let _e227 = s_8;
        return _e227;
    }
    let _e228 = x_2;
    let _e229 = before;
    let _e231 = p_2;
    uz = clamp(((_e228 - _e229) / _e231), 0f, 0.99999994f);
    let _e234 = chosen;
    let _e237 = (*c_6).lobes[_e234];
    l_9 = _e237;
    let _e239 = l_9.N;
    param_96 = _e239;
    let _e241 = l_9.T;
    param_97 = _e241;
    let _e242 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_96), (&param_97));
    frame_3 = _e242;
    let _e243 = frame_3;
    param_98 = _e243;
    let _e244 = (*wo_9);
    param_99 = _e244;
    let _e245 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_98), (&param_99));
    o_3 = _e245;
    let _e246 = (*u_5);
    let _e247 = _e246.xy;
    let _e248 = uz;
    let _e252 = l_9;
    param_100 = _e252;
    let _e253 = o_3;
    param_101 = _e253;
    param_102 = vec3<f32>(_e247.x, _e247.y, _e248);
    let _e254 = mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_100), (&param_101), (&param_102));
    ls = _e254;
    let _e256 = ls.valid;
    if !(_e256) {
        let _e258 = s_8;
        return _e258;
    }
    let _e259 = frame_3;
    param_103 = _e259;
    let _e261 = ls.wi;
    param_104 = _e261;
    let _e262 = mxc_to_world_u0028_mf33_u003b_vf3_u003b((&param_103), (&param_104));
    s_8.wi = _e262;
    let _e265 = ls.delta;
    if _e265 {
        s_8.delta = true;
        let _e268 = ls.pdf;
        let _e269 = p_2;
        let _e271 = total;
        s_8.pdf = ((_e268 * _e269) / _e271);
        let _e275 = l_9.weight;
        let _e276 = chosen;
        let _e279 = (*c_6).ms[_e276];
        let _e283 = ls.wi[2u];
        let _e285 = l_9;
        param_105 = _e285;
        param_106 = abs(_e283);
        let _e286 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_105), (&param_106));
        let _e289 = ls.value;
        let _e292 = s_8.pdf;
        s_8.weight = ((((_e275 * _e279) * _e286) * _e289) / vec3(_e292));
        let _e297 = s_8.pdf;
        s_8.valid = (_e297 > 0f);
        let _e300 = s_8;
        return _e300;
    }
    s_8.evaluate = true;
    s_8.valid = true;
    let _e303 = s_8;
    return _e303;
}

fn mxc_radical_inverse_u0028_u1_u003b_u1_u003b(i_5: ptr<function, u32>, base: ptr<function, u32>) -> f32 {
    var inv: f32;
    var f_4: f32;
    var r_3: f32;

    let _e148 = (*base);
    if (_e148 == 2u) {
        let _e150 = (*i_5);
        return (f32((reverseBits(_e150) >> bitcast<u32>(8i))) * 0.000000059604645f);
    }
    let _e156 = (*base);
    inv = (1f / f32(_e156));
    let _e159 = inv;
    f_4 = _e159;
    r_3 = 0f;
    loop {
        let _e160 = (*i_5);
        if (_e160 > 0u) {
            let _e162 = f_4;
            let _e163 = (*i_5);
            let _e164 = (*base);
            let _e168 = r_3;
            r_3 = (_e168 + (_e162 * f32((_e163 % _e164))));
            let _e170 = inv;
            let _e171 = f_4;
            f_4 = (_e171 * _e170);
            continue;
        } else {
            break;
        }
        continuing {
            let _e173 = (*base);
            let _e174 = (*i_5);
            (*i_5) = (_e174 / _e173);
        }
    }
    let _e176 = r_3;
    return min(_e176, 0.99999994f);
}

fn mxc_pcg_u0028_u1_u003b(v_5: ptr<function, u32>) -> u32 {
    var state: u32;
    var word: u32;

    let _e146 = (*v_5);
    state = ((_e146 * 747796405u) + 2891336453u);
    let _e149 = state;
    let _e150 = state;
    let _e156 = state;
    word = (((_e149 >> bitcast<u32>(((_e150 >> bitcast<u32>(28u)) + 4u))) ^ _e156) * 277803737u);
    let _e159 = word;
    let _e162 = word;
    return ((_e159 >> bitcast<u32>(22u)) ^ _e162);
}

fn mxc_uniform_u0028_u1_u003b(seed: ptr<function, u32>) -> f32 {
    var param_107: u32;

    let _e145 = (*seed);
    param_107 = _e145;
    let _e146 = mxc_pcg_u0028_u1_u003b((&param_107));
    (*seed) = _e146;
    let _e147 = (*seed);
    return (f32((_e147 >> bitcast<u32>(8i))) * 0.000000059604645f);
}

fn mxc_light_kinds_u0028_() -> i32 {
    return 7i;
}

fn mxc_light_count_u0028_() -> i32 {
    var local_18: i32;

    if false {
        local_18 = MXC_LIGHT_COUNT;
    } else {
        let _e146 = mxc_view.counts[0u];
        local_18 = _e146;
    }
    let _e147 = local_18;
    return min(_e147, 8i);
}

fn mxc_fon_albedo_u0028_f1_u003b_f1_u003b(sigma_1: ptr<function, f32>, mu_1: ptr<function, f32>) -> f32 {
    var a_3: f32;
    var c_7: f32;
    var s_9: f32;
    var param_108: f32;
    var theta: f32;
    var tail: f32;
    var local_19: f32;
    var g: f32;

    let _e153 = (*sigma_1);
    a_3 = (1f / (1f + (0.2877934f * _e153)));
    let _e157 = (*mu_1);
    c_7 = clamp(_e157, 0f, 1f);
    let _e159 = c_7;
    let _e160 = c_7;
    param_108 = (1f - (_e159 * _e160));
    let _e163 = mxc_safe_sqrt_u0028_f1_u003b((&param_108));
    s_9 = _e163;
    let _e164 = c_7;
    theta = acos(_e164);
    let _e166 = c_7;
    if (_e166 > 0.0001f) {
        let _e168 = s_9;
        let _e169 = s_9;
        let _e171 = s_9;
        let _e174 = c_7;
        local_19 = ((1f - ((_e168 * _e169) * _e171)) / _e174);
    } else {
        let _e176 = c_7;
        local_19 = (1.5f * _e176);
    }
    let _e178 = local_19;
    tail = _e178;
    let _e179 = s_9;
    let _e180 = theta;
    let _e181 = s_9;
    let _e182 = c_7;
    let _e186 = s_9;
    let _e188 = tail;
    let _e191 = s_9;
    g = (((_e179 * (_e180 - (_e181 * _e182))) + ((0.6666667f * _e186) * _e188)) - (0.6666667f * _e191));
    let _e194 = a_3;
    let _e195 = (*sigma_1);
    let _e196 = a_3;
    let _e198 = g;
    return (_e194 + (((_e195 * _e196) * _e198) * 0.31830987f));
}

fn mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b(mu_2: ptr<function, f32>, x_3: ptr<function, f32>, firstRow: ptr<function, f32>) -> vec4<f32> {
    var t_3: vec2<f32>;

    let _e147 = (*mu_2);
    let _e150 = (*x_3);
    t_3 = ((vec2<f32>(sqrt(clamp(_e147, 0f, 1f)), clamp(_e150, 0f, 1f)) * 31f) + vec2(0.5f));
    let _e157 = t_3[0u];
    let _e159 = (*firstRow);
    let _e161 = t_3[1u];
    let _e165 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, vec2<f32>((_e157 / 32f), ((_e159 + _e161) / 1654f)), 0f);
    return _e165;
}

fn mxc_table_u0028_f1_u003b_f1_u003b(mu_3: ptr<function, f32>, x_4: ptr<function, f32>) -> vec4<f32> {
    var param_109: f32;
    var param_110: f32;
    var param_111: f32;

    let _e148 = (*mu_3);
    param_109 = _e148;
    let _e149 = (*x_4);
    param_110 = _e149;
    param_111 = 0f;
    let _e150 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_109), (&param_110), (&param_111));
    return _e150;
}

fn mxc_split_sum_u0028_f1_u003b_f1_u003b(mu_4: ptr<function, f32>, alpha_8: ptr<function, f32>) -> vec2<f32> {
    var param_112: f32;
    var param_113: f32;

    let _e147 = (*alpha_8);
    let _e150 = (*mu_4);
    param_112 = _e150;
    param_113 = sqrt(max(_e147, 0f));
    let _e151 = mxc_table_u0028_f1_u003b_f1_u003b((&param_112), (&param_113));
    return _e151.xy;
}

fn mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b(mu_5: ptr<function, f32>, alpha_9: ptr<function, f32>, e: ptr<function, f32>) -> vec4<f32> {
    var s_10: f32;
    var s0_: f32;
    var x_5: f32;
    var a_4: vec4<f32>;
    var param_114: f32;
    var param_115: f32;
    var param_116: f32;
    var b_2: vec4<f32>;
    var param_117: f32;
    var param_118: f32;
    var param_119: f32;

    let _e157 = (*e);
    s_10 = (sqrt(clamp((0.5f * (_e157 - 1f)), 0f, 1f)) * 31f);
    let _e163 = s_10;
    s0_ = min(floor(_e163), 30f);
    let _e166 = (*alpha_9);
    x_5 = sqrt(max(_e166, 0f));
    let _e169 = s0_;
    let _e172 = (*mu_5);
    param_114 = _e172;
    let _e173 = x_5;
    param_115 = _e173;
    param_116 = (32f * (1f + _e169));
    let _e174 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_114), (&param_115), (&param_116));
    a_4 = _e174;
    let _e175 = s0_;
    let _e178 = (*mu_5);
    param_117 = _e178;
    let _e179 = x_5;
    param_118 = _e179;
    param_119 = (32f * (2f + _e175));
    let _e180 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_117), (&param_118), (&param_119));
    b_2 = _e180;
    let _e181 = a_4;
    let _e182 = b_2;
    let _e183 = s_10;
    let _e184 = s0_;
    return mix(_e181, _e182, vec4((_e183 - _e184)));
}

fn mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b(mu_6: ptr<function, f32>, alpha_10: ptr<function, f32>, eta_1: ptr<function, f32>) -> f32 {
    var e_1: f32;
    var local_20: f32;
    var param_120: f32;
    var param_121: f32;
    var param_122: f32;

    let _e151 = (*eta_1);
    if (_e151 >= 1f) {
        let _e153 = (*eta_1);
        local_20 = _e153;
    } else {
        let _e154 = (*eta_1);
        local_20 = (1f / max(_e154, 0.001f));
    }
    let _e157 = local_20;
    e_1 = _e157;
    let _e158 = (*mu_6);
    param_120 = _e158;
    let _e159 = (*alpha_10);
    param_121 = _e159;
    let _e160 = e_1;
    param_122 = _e160;
    let _e161 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_120), (&param_121), (&param_122));
    return _e161.x;
}

fn mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_10: ptr<function, MxcLobe>, wo_10: ptr<function, vec3<f32>>, ms: ptr<function, vec3<f32>>) -> vec3<f32> {
    var mu_7: f32;
    var alpha_11: f32;
    var param_123: vec2<f32>;
    var e_2: vec3<f32>;
    var param_124: f32;
    var param_125: f32;
    var param_126: f32;
    var ab: vec2<f32>;
    var param_127: f32;
    var param_128: f32;
    var f0_: vec3<f32>;
    var param_129: MxcLobe;
    var param_130: f32;
    var param_131: bool;
    var f90_: vec3<f32>;
    var param_132: MxcLobe;
    var param_133: f32;
    var param_134: bool;
    var tint_1: vec3<f32>;
    var local_21: vec3<f32>;
    var param_135: vec2<f32>;
    var param_136: MxcLobe;
    var param_137: f32;
    var param_138: bool;
    var param_139: f32;
    var param_140: f32;
    var phi_2241_: bool;
    var phi_2248_: bool;
    var phi_2266_: bool;

    let _e173 = (*wo_10)[2u];
    mu_7 = clamp(_e173, 0f, 1f);
    let _e176 = (*l_10).kind;
    let _e177 = (_e176 == 1i);
    phi_2241_ = _e177;
    if !(_e177) {
        let _e180 = (*l_10).kind;
        phi_2241_ = (_e180 == 2i);
    }
    let _e183 = phi_2241_;
    phi_2248_ = _e183;
    if !(_e183) {
        let _e186 = (*l_10).kind;
        phi_2248_ = (_e186 == 3i);
    }
    let _e189 = phi_2248_;
    if _e189 {
        let _e192 = (*l_10).alpha[0u];
        let _e195 = (*l_10).alpha[1u];
        alpha_11 = sqrt((_e192 * _e195));
        let _e199 = (*l_10).kind;
        let _e200 = (_e199 == 1i);
        phi_2266_ = _e200;
        if _e200 {
            let _e202 = (*l_10).alpha;
            param_123 = _e202;
            let _e203 = mxc_is_delta_u0028_vf2_u003b((&param_123));
            phi_2266_ = !(_e203);
        }
        let _e206 = phi_2266_;
        if _e206 {
            let _e207 = mu_7;
            param_124 = _e207;
            let _e208 = alpha_11;
            param_125 = _e208;
            let _e210 = (*l_10).eta;
            param_126 = _e210;
            let _e211 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_124), (&param_125), (&param_126));
            e_2 = vec3(_e211);
            let _e213 = e_2;
            let _e215 = (*l_10).c0_;
            let _e217 = (*ms);
            return clamp(((_e213 * _e215) * _e217), vec3(0f), vec3(1f));
        }
        let _e222 = mu_7;
        param_127 = _e222;
        let _e223 = alpha_11;
        param_128 = _e223;
        let _e224 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_127), (&param_128));
        ab = _e224;
        let _e225 = (*l_10);
        param_129 = _e225;
        param_130 = 1f;
        param_131 = true;
        let _e226 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_129), (&param_130), (&param_131));
        f0_ = _e226;
        let _e227 = (*l_10);
        param_132 = _e227;
        param_133 = 0f;
        param_134 = true;
        let _e228 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_132), (&param_133), (&param_134));
        f90_ = _e228;
        let _e230 = (*l_10).kind;
        if (_e230 == 1i) {
            let _e233 = (*l_10).c0_;
            local_21 = _e233;
        } else {
            local_21 = vec3<f32>(1f, 1f, 1f);
        }
        let _e234 = local_21;
        tint_1 = _e234;
        let _e236 = (*l_10).alpha;
        param_135 = _e236;
        let _e237 = mxc_is_delta_u0028_vf2_u003b((&param_135));
        if _e237 {
            let _e238 = (*l_10);
            param_136 = _e238;
            let _e239 = mu_7;
            param_137 = _e239;
            param_138 = true;
            let _e240 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_136), (&param_137), (&param_138));
            let _e241 = tint_1;
            return (_e240 * _e241);
        }
        let _e243 = f0_;
        let _e245 = ab[0u];
        let _e247 = f90_;
        let _e249 = ab[1u];
        let _e252 = tint_1;
        let _e254 = (*ms);
        return clamp(((((_e243 * _e245) + (_e247 * _e249)) * _e252) * _e254), vec3(0f), vec3(1f));
    }
    let _e260 = (*l_10).kind;
    if (_e260 == 4i) {
        let _e263 = (*l_10).c0_;
        let _e265 = (*l_10).p0_;
        param_139 = _e265;
        let _e266 = mu_7;
        param_140 = _e266;
        let _e267 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_139), (&param_140));
        return (_e263 * _e267);
    }
    let _e270 = (*l_10).kind;
    if (_e270 == 8i) {
        let _e273 = (*l_10).c0_;
        return _e273;
    }
    let _e275 = (*l_10).c0_;
    return _e275;
}

fn mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_11: ptr<function, MxcLobe>, woLocal: ptr<function, vec3<f32>>, ms_1: ptr<function, vec3<f32>>) -> f32 {
    var param_141: MxcLobe;
    var param_142: vec3<f32>;
    var param_143: vec3<f32>;
    var param_144: vec3<f32>;

    let _e151 = (*l_11).weight;
    if all((_e151 == vec3<f32>(0f, 0f, 0f))) {
        return 0f;
    }
    let _e155 = (*l_11).weight;
    let _e156 = (*l_11);
    param_141 = _e156;
    let _e157 = (*woLocal);
    param_142 = _e157;
    let _e158 = (*ms_1);
    param_143 = _e158;
    let _e159 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_141), (&param_142), (&param_143));
    param_144 = (_e155 * _e159);
    let _e161 = mxc_luminance_u0028_vf3_u003b((&param_144));
    return (max(_e161, 0f) + 0.0001f);
}

fn mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b(mu_8: ptr<function, f32>, alpha_12: ptr<function, f32>, eta_2: ptr<function, f32>) -> f32 {
    var param_145: f32;
    var param_146: f32;
    var param_147: f32;
    var param_148: f32;
    var param_149: f32;
    var param_150: f32;

    let _e152 = (*eta_2);
    if (_e152 >= 1f) {
        let _e154 = (*mu_8);
        param_145 = _e154;
        let _e155 = (*alpha_12);
        param_146 = _e155;
        let _e156 = (*eta_2);
        param_147 = _e156;
        let _e157 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_145), (&param_146), (&param_147));
        return _e157.y;
    }
    let _e159 = (*eta_2);
    let _e162 = (*mu_8);
    param_148 = _e162;
    let _e163 = (*alpha_12);
    param_149 = _e163;
    param_150 = (1f / max(_e159, 0.001f));
    let _e164 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_148), (&param_149), (&param_150));
    return _e164.z;
}

fn mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_12: ptr<function, MxcLobe>) -> bool {
    let _e145 = (*l_12).eta;
    return (abs((_e145 - 1f)) < 0.0001f);
}

fn mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_13: ptr<function, MxcLobe>, wo_11: ptr<function, vec3<f32>>) -> vec3<f32> {
    var microfacet: bool;
    var param_151: vec2<f32>;
    var alpha_13: f32;
    var param_152: MxcLobe;
    var e_3: f32;
    var param_153: MxcLobe;
    var param_154: bool;
    var param_155: f32;
    var param_156: f32;
    var param_157: f32;
    var k_3: vec3<f32>;
    var ab_1: vec2<f32>;
    var param_158: f32;
    var param_159: f32;
    var e_4: f32;
    var param_160: MxcLobe;
    var param_161: f32;
    var param_162: bool;
    var phi_2115_: bool;
    var phi_2122_: bool;
    var phi_2131_: bool;
    var phi_2147_: bool;
    var phi_2159_: bool;

    let _e164 = (*l_13).kind;
    let _e165 = (_e164 == 1i);
    phi_2115_ = _e165;
    if !(_e165) {
        let _e168 = (*l_13).kind;
        phi_2115_ = (_e168 == 2i);
    }
    let _e171 = phi_2115_;
    phi_2122_ = _e171;
    if !(_e171) {
        let _e174 = (*l_13).kind;
        phi_2122_ = (_e174 == 3i);
    }
    let _e177 = phi_2122_;
    microfacet = _e177;
    let _e178 = microfacet;
    let _e179 = !(_e178);
    phi_2131_ = _e179;
    if !(_e179) {
        let _e182 = (*l_13).alpha;
        param_151 = _e182;
        let _e183 = mxc_is_delta_u0028_vf2_u003b((&param_151));
        phi_2131_ = _e183;
    }
    let _e185 = phi_2131_;
    if _e185 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e188 = (*l_13).alpha[0u];
    let _e191 = (*l_13).alpha[1u];
    alpha_13 = sqrt((_e188 * _e191));
    let _e195 = (*l_13).kind;
    let _e196 = (_e195 == 1i);
    phi_2147_ = _e196;
    if _e196 {
        let _e197 = (*l_13);
        param_152 = _e197;
        let _e198 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_152));
        phi_2147_ = _e198;
    }
    let _e200 = phi_2147_;
    if _e200 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e202 = (*l_13).kind;
    let _e203 = (_e202 == 1i);
    phi_2159_ = _e203;
    if _e203 {
        let _e205 = (*l_13).mode;
        phi_2159_ = ((_e205 & 4i) == 0i);
    }
    let _e209 = phi_2159_;
    if _e209 {
        let _e211 = (*wo_11)[2u];
        let _e214 = (*wo_11)[2u];
        let _e216 = (*l_13);
        param_153 = _e216;
        param_154 = (_e214 >= 0f);
        let _e217 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_153), (&param_154));
        param_155 = abs(_e211);
        let _e218 = alpha_13;
        param_156 = _e218;
        param_157 = _e217;
        let _e219 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_155), (&param_156), (&param_157));
        e_3 = _e219;
        let _e220 = e_3;
        k_3 = vec3((1f / max(_e220, 0.05f)));
        let _e224 = k_3;
        return _e224;
    }
    let _e226 = (*wo_11)[2u];
    param_158 = max(_e226, 0f);
    let _e228 = alpha_13;
    param_159 = _e228;
    let _e229 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_158), (&param_159));
    ab_1 = _e229;
    let _e231 = ab_1[0u];
    let _e233 = ab_1[1u];
    e_4 = (_e231 + _e233);
    let _e235 = (*l_13);
    param_160 = _e235;
    param_161 = 1f;
    param_162 = true;
    let _e236 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_160), (&param_161), (&param_162));
    let _e237 = e_4;
    let _e240 = e_4;
    return (vec3(1f) + ((_e236 * (1f - _e237)) / vec3(max(_e240, 0.05f))));
}

fn mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b(c_8: ptr<function, MxcClosure>, wo_12: ptr<function, vec3<f32>>) {
    var k_4: i32;
    var l_14: MxcLobe;
    var o_4: vec3<f32>;
    var param_163: vec3<f32>;
    var param_164: vec3<f32>;
    var param_165: mat3x3<f32>;
    var param_166: vec3<f32>;
    var param_167: MxcLobe;
    var param_168: vec3<f32>;
    var param_169: MxcLobe;
    var param_170: vec3<f32>;
    var param_171: vec3<f32>;

    (*c_8).choiceTotal = 0f;
    k_4 = 0i;
    loop {
        let _e158 = k_4;
        let _e160 = (*c_8).count;
        if (_e158 < _e160) {
            let _e162 = k_4;
            let _e165 = (*c_8).lobes[_e162];
            l_14 = _e165;
            let _e166 = k_4;
            (*c_8).ms[_e166] = vec3<f32>(1f, 1f, 1f);
            let _e169 = k_4;
            (*c_8).choice[_e169] = 0f;
            let _e173 = l_14.weight;
            if all((_e173 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e177 = l_14.N;
            param_163 = _e177;
            let _e179 = l_14.T;
            param_164 = _e179;
            let _e180 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_163), (&param_164));
            param_165 = _e180;
            let _e181 = (*wo_12);
            param_166 = _e181;
            let _e182 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_165), (&param_166));
            o_4 = _e182;
            let _e183 = k_4;
            let _e184 = l_14;
            param_167 = _e184;
            let _e185 = o_4;
            param_168 = _e185;
            let _e186 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_167), (&param_168));
            (*c_8).ms[_e183] = _e186;
            let _e189 = k_4;
            let _e190 = k_4;
            let _e191 = l_14;
            param_169 = _e191;
            let _e192 = o_4;
            param_170 = _e192;
            let _e195 = (*c_8).ms[_e190];
            param_171 = _e195;
            let _e196 = mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_169), (&param_170), (&param_171));
            (*c_8).choice[_e189] = _e196;
            let _e199 = k_4;
            let _e202 = (*c_8).choice[_e199];
            let _e204 = (*c_8).choiceTotal;
            (*c_8).choiceTotal = (_e204 + _e202);
            continue;
        } else {
            break;
        }
        continuing {
            let _e207 = k_4;
            k_4 = (_e207 + 1i);
        }
    }
    return;
}

fn mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_15: ptr<function, MxcLobe>, wo_13: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_172: MxcLobe;
    var param_173: vec3<f32>;
    var param_174: MxcLobe;
    var param_175: vec3<f32>;
    var param_176: vec3<f32>;

    let _e150 = (*l_15);
    param_172 = _e150;
    let _e151 = (*wo_13);
    param_173 = _e151;
    let _e152 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_172), (&param_173));
    let _e153 = (*l_15);
    param_174 = _e153;
    let _e154 = (*wo_13);
    param_175 = _e154;
    param_176 = _e152;
    let _e155 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_174), (&param_175), (&param_176));
    return _e155;
}

fn mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_16: ptr<function, MxcLobe>, wo_14: ptr<function, vec3<f32>>) -> vec3<f32> {
    var white: MxcLobe;
    var param_177: MxcLobe;
    var param_178: vec3<f32>;
    var param_179: MxcLobe;
    var param_180: vec3<f32>;
    var phi_2380_: bool;

    let _e151 = (*l_16).kind;
    let _e152 = (_e151 == 9i);
    phi_2380_ = _e152;
    if !(_e152) {
        let _e155 = (*l_16).kind;
        phi_2380_ = (_e155 == 10i);
    }
    let _e158 = phi_2380_;
    if _e158 {
        let _e159 = (*l_16);
        white = _e159;
        white.c0_ = vec3<f32>(1f, 1f, 1f);
        let _e161 = white;
        param_177 = _e161;
        let _e162 = (*wo_14);
        param_178 = _e162;
        let _e163 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_177), (&param_178));
        return _e163;
    }
    let _e164 = (*l_16);
    param_179 = _e164;
    let _e165 = (*wo_14);
    param_180 = _e165;
    let _e166 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_179), (&param_180));
    return _e166;
}

fn mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b(v_6: ptr<function, vec3<f32>>, fallback: ptr<function, vec3<f32>>) -> vec3<f32> {
    var l2_1: f32;
    var local_22: vec3<f32>;

    let _e147 = (*v_6);
    let _e148 = (*v_6);
    l2_1 = dot(_e147, _e148);
    let _e150 = l2_1;
    if (_e150 > 0.00000000000000000001f) {
        let _e152 = (*v_6);
        let _e153 = l2_1;
        local_22 = (_e152 * inverseSqrt(_e153));
    } else {
        let _e156 = (*fallback);
        local_22 = _e156;
    }
    let _e157 = local_22;
    return _e157;
}

fn mxc_normalmap_u0028_vf3_u003b_vf2_u003b_vf3_u003b_vf3_u003b_vf3_u003b(sampleValue: ptr<function, vec3<f32>>, scale: ptr<function, vec2<f32>>, N_1: ptr<function, vec3<f32>>, T_1: ptr<function, vec3<f32>>, B: ptr<function, vec3<f32>>) -> vec3<f32> {
    var v_7: vec3<f32>;
    var param_181: vec3<f32>;
    var param_182: vec3<f32>;

    let _e151 = (*sampleValue);
    v_7 = ((_e151 * 2f) - vec3(1f));
    let _e155 = (*scale);
    let _e156 = v_7;
    let _e158 = (_e156.xy * _e155);
    v_7[0u] = _e158.x;
    v_7[1u] = _e158.y;
    let _e163 = (*T_1);
    let _e165 = v_7[0u];
    let _e167 = (*B);
    let _e169 = v_7[1u];
    let _e172 = (*N_1);
    let _e174 = v_7[2u];
    param_181 = (((_e163 * _e165) + (_e167 * _e169)) + (_e172 * _e174));
    let _e177 = (*N_1);
    param_182 = _e177;
    let _e178 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_181), (&param_182));
    return _e178;
}

fn mxc_hsv_to_rgb_u0028_vf3_u003b(hsv: ptr<function, vec3<f32>>) -> vec3<f32> {
    var k_5: vec3<f32>;

    let _e146 = (*hsv)[0u];
    k_5 = clamp((abs(((fract((vec3(_e146) + vec3<f32>(0f, 0.6666667f, 0.33333334f))) * 6f) - vec3(3f))) - vec3(1f)), vec3(0f), vec3(1f));
    let _e160 = (*hsv)[2u];
    let _e161 = k_5;
    let _e163 = (*hsv)[1u];
    return (mix(vec3<f32>(1f, 1f, 1f), _e161, vec3(_e163)) * _e160);
}

fn mxc_address_u0028_f1_u003b_i1_u003b(x_6: ptr<function, f32>, mode: ptr<function, i32>) -> bool {
    let _e145 = (*mode);
    if (_e145 == 0i) {
        let _e147 = (*x_6);
        let _e149 = (*x_6);
        return ((_e147 >= 0f) && (_e149 <= 1f));
    }
    let _e152 = (*mode);
    if (_e152 == 1i) {
        let _e154 = (*x_6);
        (*x_6) = clamp(_e154, 0f, 1f);
    } else {
        let _e156 = (*mode);
        if (_e156 == 2i) {
            let _e158 = (*x_6);
            (*x_6) = fract(_e158);
        } else {
            let _e160 = (*x_6);
            (*x_6) = (1f - abs(((_e160 - (floor((_e160 / 2f)) * 2f)) - 1f)));
        }
    }
    return true;
}

fn mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(image_texture: texture_2d<f32>, image_sampler: sampler, uv_1: ptr<function, vec2<f32>>, fallback_1: ptr<function, vec4<f32>>, uaddress: ptr<function, i32>, vaddress: ptr<function, i32>, filtertype: ptr<function, i32>, missing: ptr<function, bool>) -> vec4<f32> {
    var dx: vec2<f32>;
    var dy: vec2<f32>;
    var st: vec2<f32>;
    var param_183: f32;
    var param_184: i32;
    var param_185: f32;
    var param_186: i32;
    var size_2: vec2<f32>;
    var phi_1667_: bool;

    let _e159 = (*uv_1);
    let _e160 = dpdx(_e159);
    let _e161 = mxc_texture_footprint;
    let _e162 = mxc_texture_footprint;
    dx = (_e160 * vec2<f32>(_e161, -(_e162)));
    let _e166 = (*uv_1);
    let _e167 = dpdy(_e166);
    let _e168 = mxc_texture_footprint;
    let _e169 = mxc_texture_footprint;
    dy = (_e167 * vec2<f32>(_e168, -(_e169)));
    let _e173 = (*uv_1);
    st = _e173;
    let _e174 = (*missing);
    if _e174 {
        let _e175 = (*fallback_1);
        return _e175;
    }
    let _e177 = st[0u];
    param_183 = _e177;
    let _e178 = (*uaddress);
    param_184 = _e178;
    let _e179 = mxc_address_u0028_f1_u003b_i1_u003b((&param_183), (&param_184));
    let _e180 = param_183;
    st[0u] = _e180;
    let _e182 = !(_e179);
    phi_1667_ = _e182;
    if !(_e182) {
        let _e185 = st[1u];
        param_185 = _e185;
        let _e186 = (*vaddress);
        param_186 = _e186;
        let _e187 = mxc_address_u0028_f1_u003b_i1_u003b((&param_185), (&param_186));
        let _e188 = param_185;
        st[1u] = _e188;
        phi_1667_ = !(_e187);
    }
    let _e192 = phi_1667_;
    if _e192 {
        let _e193 = (*fallback_1);
        return _e193;
    }
    let _e195 = st[1u];
    st[1u] = (1f - _e195);
    let _e198 = (*filtertype);
    if (_e198 == 1i) {
        let _e200 = textureDimensions(image_texture, 0i);
        size_2 = vec2<f32>(vec2<i32>(_e200));
        let _e203 = st;
        let _e204 = size_2;
        let _e207 = size_2;
        let _e213 = size_2;
        let _e215 = textureSampleLevel(image_texture, image_sampler, ((min(floor((_e203 * _e204)), (_e207 - vec2(1f))) + vec2(0.5f)) / _e213), 0f);
        return _e215;
    }
    let _e216 = st;
    let _e217 = dx;
    let _e218 = dy;
    let _e219 = textureSampleGrad(image_texture, image_sampler, _e216, _e217, _e218);
    return _e219;
}

fn mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b(g_1: ptr<function, MxcGeometry>, wo_15: ptr<function, vec3<f32>>, c_9: ptr<function, MxcClosure>) {
    var v3_: vec2<f32>;
    var v4_: vec2<f32>;
    var v8_: f32;
    var param_187: vec2<f32>;
    var param_188: vec4<f32>;
    var param_189: i32;
    var param_190: i32;
    var param_191: i32;
    var param_192: bool;
    var v10_: f32;
    var v11_: f32;
    var v13_: f32;
    var param_193: vec2<f32>;
    var param_194: vec4<f32>;
    var param_195: i32;
    var param_196: i32;
    var param_197: i32;
    var param_198: bool;
    var v14_: f32;
    var v20_: f32;
    var param_199: vec2<f32>;
    var param_200: vec4<f32>;
    var param_201: i32;
    var param_202: i32;
    var param_203: i32;
    var param_204: bool;
    var v21_: f32;
    var v25_: f32;
    var param_205: vec2<f32>;
    var param_206: vec4<f32>;
    var param_207: i32;
    var param_208: i32;
    var param_209: i32;
    var param_210: bool;
    var v26_: f32;
    var v28_: f32;
    var param_211: vec2<f32>;
    var param_212: vec4<f32>;
    var param_213: i32;
    var param_214: i32;
    var param_215: i32;
    var param_216: bool;
    var v29_: f32;
    var v31_: f32;
    var v32_: f32;
    var v34_: f32;
    var v35_: f32;
    var v36_: vec3<f32>;
    var v38_: vec3<f32>;
    var v39_: vec3<f32>;
    var param_217: vec3<f32>;
    var v40_: vec3<f32>;
    var v41_: vec3<f32>;
    var v43_: vec3<f32>;
    var v44_: vec3<f32>;
    var v45_: vec3<f32>;
    var v46_: vec3<f32>;
    var v48_: vec3<f32>;
    var param_218: vec2<f32>;
    var param_219: vec4<f32>;
    var param_220: i32;
    var param_221: i32;
    var param_222: i32;
    var param_223: bool;
    var v49_: vec3<f32>;
    var v50_: vec3<f32>;
    var v51_: vec3<f32>;
    var v52_: vec3<f32>;
    var param_224: vec3<f32>;
    var param_225: vec2<f32>;
    var param_226: vec3<f32>;
    var param_227: vec3<f32>;
    var param_228: vec3<f32>;
    var v55_: f32;
    var v56_: f32;
    var v57_: vec2<f32>;
    var lobe0_: MxcLobe;
    var param_229: vec3<f32>;
    var param_230: vec3<f32>;
    var e1_: vec3<f32>;
    var param_231: vec3<f32>;
    var param_232: vec3<f32>;
    var param_233: mat3x3<f32>;
    var param_234: vec3<f32>;
    var param_235: MxcLobe;
    var param_236: vec3<f32>;
    var w2_: vec3<f32>;
    var lobe3_: MxcLobe;
    var param_237: vec3<f32>;
    var param_238: vec3<f32>;
    var param_239: MxcClosure;
    var param_240: vec3<f32>;

    let _e239 = (*g_1).uv;
    v3_ = _e239;
    let _e240 = v3_;
    v4_ = (_e240 * vec2<f32>(3f, 3f));
    let _e243 = mxc_params.missing_textures;
    let _e246 = v4_;
    param_187 = _e246;
    param_188 = vec4<f32>(0f, 0f, 0f, 0f);
    param_189 = 2i;
    param_190 = 2i;
    param_191 = 0i;
    param_192 = ((_e243 & 1u) != 0u);
    let _e247 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_0_texture, mxc_texture_0_sampler, (&param_187), (&param_188), (&param_189), (&param_190), (&param_191), (&param_192));
    v8_ = _e247.x;
    let _e249 = v8_;
    v10_ = max(_e249, 0.00001f);
    let _e251 = v10_;
    v11_ = (0.853f / _e251);
    let _e254 = mxc_params.missing_textures;
    let _e257 = v4_;
    param_193 = _e257;
    param_194 = vec4<f32>(0f, 0f, 0f, 0f);
    param_195 = 2i;
    param_196 = 2i;
    param_197 = 0i;
    param_198 = ((_e254 & 2u) != 0u);
    let _e258 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_1_texture, mxc_texture_1_sampler, (&param_193), (&param_194), (&param_195), (&param_196), (&param_197), (&param_198));
    v13_ = _e258.x;
    let _e260 = v11_;
    let _e261 = v13_;
    v14_ = (_e260 * _e261);
    let _e264 = mxc_params.missing_textures;
    let _e267 = v4_;
    param_199 = _e267;
    param_200 = vec4<f32>(0f, 0f, 0f, 0f);
    param_201 = 2i;
    param_202 = 2i;
    param_203 = 0i;
    param_204 = ((_e264 & 4u) != 0u);
    let _e268 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_2_texture, mxc_texture_2_sampler, (&param_199), (&param_200), (&param_201), (&param_202), (&param_203), (&param_204));
    v20_ = _e268.x;
    let _e270 = v20_;
    v21_ = (0.248f * _e270);
    let _e273 = mxc_params.missing_textures;
    let _e276 = v4_;
    param_205 = _e276;
    param_206 = vec4<f32>(0f, 0f, 0f, 0f);
    param_207 = 2i;
    param_208 = 2i;
    param_209 = 0i;
    param_210 = ((_e273 & 8u) != 0u);
    let _e277 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_3_texture, mxc_texture_3_sampler, (&param_205), (&param_206), (&param_207), (&param_208), (&param_209), (&param_210));
    v25_ = _e277.x;
    let _e279 = v25_;
    v26_ = (0.083f * _e279);
    let _e282 = mxc_params.missing_textures;
    let _e285 = v4_;
    param_211 = _e285;
    param_212 = vec4<f32>(0f, 0f, 0f, 0f);
    param_213 = 2i;
    param_214 = 2i;
    param_215 = 0i;
    param_216 = ((_e282 & 16u) != 0u);
    let _e286 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_4_texture, mxc_texture_4_sampler, (&param_211), (&param_212), (&param_213), (&param_214), (&param_215), (&param_216));
    v28_ = _e286.x;
    let _e288 = v26_;
    let _e289 = v28_;
    v29_ = (_e288 + _e289);
    let _e291 = v29_;
    v31_ = (_e291 - 0.35f);
    let _e293 = v31_;
    v32_ = (_e293 * 0.083f);
    let _e295 = v25_;
    v34_ = (0.787f * _e295);
    let _e297 = v29_;
    let _e298 = v34_;
    v35_ = (_e297 * _e298);
    let _e300 = v32_;
    let _e301 = v35_;
    v36_ = vec3<f32>(_e300, 0f, _e301);
    let _e303 = v36_;
    v38_ = (_e303 + vec3<f32>(0.048065394f, 1f, 0.661876f));
    let _e305 = v38_;
    param_217 = _e305;
    let _e306 = mxc_hsv_to_rgb_u0028_vf3_u003b((&param_217));
    v39_ = _e306;
    let _e307 = v39_;
    let _e308 = v21_;
    v40_ = mix(_e307, vec3<f32>(0.56372f, 0.56372f, 0.56372f), vec3(_e308));
    let _e311 = v40_;
    let _e312 = v28_;
    v41_ = (_e311 * _e312);
    let _e314 = v28_;
    v43_ = (vec3<f32>(0.263273f, 0.263273f, 0.263273f) * _e314);
    let _e316 = v43_;
    let _e317 = v41_;
    let _e318 = v8_;
    v44_ = mix(_e316, _e317, vec3(_e318));
    let _e321 = v44_;
    v45_ = clamp(_e321, vec3<f32>(0f, 0f, 0f), vec3<f32>(1f, 1f, 1f));
    let _e323 = v45_;
    v46_ = clamp(_e323, vec3<f32>(0f, 0f, 0f), vec3<f32>(1f, 1f, 1f));
    let _e326 = mxc_params.missing_textures;
    let _e329 = v4_;
    param_218 = _e329;
    param_219 = vec4<f32>(0f, 0f, 0f, 1f);
    param_220 = 2i;
    param_221 = 2i;
    param_222 = 0i;
    param_223 = ((_e326 & 32u) != 0u);
    let _e330 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_5_texture, mxc_texture_5_sampler, (&param_218), (&param_219), (&param_220), (&param_221), (&param_222), (&param_223));
    v48_ = _e330.xyz;
    let _e333 = (*g_1).N;
    v49_ = _e333;
    let _e335 = (*g_1).T;
    v50_ = _e335;
    let _e337 = (*g_1).B;
    v51_ = _e337;
    let _e338 = v48_;
    param_224 = _e338;
    param_225 = vec2<f32>(1f, 1f);
    let _e339 = v49_;
    param_226 = _e339;
    let _e340 = v50_;
    param_227 = _e340;
    let _e341 = v51_;
    param_228 = _e341;
    let _e342 = mxc_normalmap_u0028_vf3_u003b_vf2_u003b_vf3_u003b_vf3_u003b_vf3_u003b((&param_224), (&param_225), (&param_226), (&param_227), (&param_228));
    v52_ = _e342;
    let _e343 = v14_;
    let _e344 = v14_;
    v55_ = (_e343 * _e344);
    let _e346 = v55_;
    v56_ = clamp(_e346, 0.0000001f, 1f);
    let _e348 = v56_;
    let _e349 = v56_;
    v57_ = vec2<f32>(_e348, _e349);
    (*c_9).emission = vec3<f32>(0f, 0f, 0f);
    (*c_9).transparency = vec3<f32>(0f, 0f, 0f);
    lobe0_.kind = 1i;
    lobe0_.mode = 1i;
    let _e355 = v52_;
    param_229 = _e355;
    let _e357 = (*g_1).N;
    param_230 = _e357;
    let _e358 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_229), (&param_230));
    lobe0_.N = _e358;
    let _e360 = v50_;
    lobe0_.T = _e360;
    let _e362 = v57_;
    lobe0_.alpha = _e362;
    lobe0_.eta = 1.5f;
    lobe0_.c0_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.p0_ = 0f;
    lobe0_.p1_ = 1f;
    lobe0_.film = vec3<f32>(0f, 0f, 0f);
    lobe0_.tau = vec3<f32>(0f, 0f, 0f);
    lobe0_.tauEta = 1f;
    let _e374 = lobe0_.N;
    param_231 = _e374;
    let _e376 = lobe0_.T;
    param_232 = _e376;
    let _e377 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_231), (&param_232));
    param_233 = _e377;
    let _e378 = (*wo_15);
    param_234 = _e378;
    let _e379 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_233), (&param_234));
    let _e380 = lobe0_;
    param_235 = _e380;
    param_236 = _e379;
    let _e381 = mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_235), (&param_236));
    e1_ = _e381;
    let _e382 = e1_;
    w2_ = (vec3<f32>(1f, 1f, 1f) - _e382);
    lobe3_.kind = 4i;
    lobe3_.mode = 1i;
    let _e386 = v52_;
    param_237 = _e386;
    let _e388 = (*g_1).N;
    param_238 = _e388;
    let _e389 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_237), (&param_238));
    lobe3_.N = _e389;
    let _e392 = (*g_1).T;
    lobe3_.T = _e392;
    lobe3_.alpha = vec2<f32>(0f, 0f);
    lobe3_.eta = 1.5f;
    let _e396 = v46_;
    lobe3_.c0_ = _e396;
    lobe3_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.p0_ = 0f;
    lobe3_.p1_ = 1f;
    lobe3_.film = vec3<f32>(0f, 0f, 0f);
    lobe3_.tau = vec3<f32>(0f, 0f, 0f);
    lobe3_.tauEta = 1f;
    lobe0_.weight = vec3<f32>(1f, 1f, 1f);
    let _e406 = lobe0_;
    (*c_9).lobes[0i] = _e406;
    let _e409 = w2_;
    lobe3_.weight = _e409;
    let _e411 = lobe3_;
    (*c_9).lobes[1i] = _e411;
    (*c_9).count = 2i;
    let _e415 = (*c_9);
    param_239 = _e415;
    let _e416 = (*wo_15);
    param_240 = _e416;
    mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b((&param_239), (&param_240));
    let _e417 = param_239;
    (*c_9) = _e417;
    return;
}

fn mxc_closure_seed_u0028_u1_u003b(seed_1: ptr<function, u32>) {
    return;
}

fn main_1() {
    var g_2: MxcGeometry;
    var N_2: vec3<f32>;
    var param_241: vec3<f32>;
    var param_242: vec3<f32>;
    var wo_16: vec3<f32>;
    var param_243: vec3<f32>;
    var param_244: vec3<f32>;
    var facing: f32;
    var handedness: f32;
    var frame_4: mat3x3<f32>;
    var param_245: vec3<f32>;
    var param_246: vec3<f32>;
    var param_247: vec3<f32>;
    var param_248: vec3<f32>;
    var objectFrame: mat3x3<f32>;
    var param_249: vec3<f32>;
    var param_250: vec3<f32>;
    var param_251: u32;
    var param_252: u32;
    var param_253: u32;
    var param_254: u32;
    var c_10: MxcClosure;
    var param_255: MxcGeometry;
    var param_256: vec3<f32>;
    var param_257: MxcClosure;
    var radiance: vec3<f32>;
    var lights: i32;
    var kinds: i32;
    var image: bool;
    var n_1: i32;
    var local_23: i32;
    var seed_2: u32;
    var param_258: u32;
    var param_259: u32;
    var param_260: u32;
    var pixel: u32;
    var param_261: u32;
    var param_262: u32;
    var shift: vec4<f32>;
    var param_263: u32;
    var param_264: u32;
    var param_265: u32;
    var param_266: u32;
    var sum: vec3<f32>;
    var b_3: i32;
    var batchLights: i32;
    var batchSamples: i32;
    var local_24: i32;
    var index: u32;
    var choice: vec4<f32>;
    var param_267: u32;
    var param_268: u32;
    var param_269: u32;
    var param_270: u32;
    var param_271: u32;
    var param_272: u32;
    var param_273: u32;
    var param_274: u32;
    var smp: MxcSample;
    var param_275: MxcClosure;
    var param_276: vec3<f32>;
    var param_277: vec3<f32>;
    var above_4: bool;
    var seen: vec3<f32>;
    var local_25: vec3<f32>;
    var local_26: vec3<f32>;
    var param_278: vec3<f32>;
    var param_279: vec3<f32>;
    var param_280: vec3<f32>;
    var w_1: f32;
    var local_27: f32;
    var param_281: vec3<f32>;
    var param_282: f32;
    var param_283: vec3<f32>;
    var param_284: f32;
    var param_285: f32;
    var m_5: vec3<f32>;
    var lightPdf: f32;
    var imageWi: vec3<f32>;
    var imageSeen: vec3<f32>;
    var v_8: vec4<f32>;
    var param_286: u32;
    var param_287: u32;
    var param_288: u32;
    var param_289: vec4<f32>;
    var param_290: f32;
    var param_291: vec3<f32>;
    var param_292: f32;
    var param_293: vec3<f32>;
    var j_2: i32;
    var wi_6: vec3<f32>;
    var incoming: vec3<f32>;
    var use_: bool;
    var strategy: i32;
    var local_28: i32;
    var light: vec4<f32>;
    var directional: bool;
    var param_294: vec3<f32>;
    var param_295: vec3<f32>;
    var d_8: vec3<f32>;
    var d2_: f32;
    var spot: vec4<f32>;
    var f_5: vec3<f32>;
    var pdf_2: f32;
    var param_296: MxcClosure;
    var param_297: vec3<f32>;
    var param_298: vec3<f32>;
    var param_299: bool;
    var param_300: f32;
    var w_2: f32;
    var local_29: f32;
    var param_301: vec3<f32>;
    var param_302: f32;
    var param_303: vec3<f32>;
    var param_304: f32;
    var param_305: f32;
    var w_3: f32;
    var param_306: vec3<f32>;
    var param_307: f32;
    var param_308: f32;
    var coverage: f32;
    var param_309: vec3<f32>;
    var phi_657_: bool;
    var phi_668_: bool;
    var phi_730_: bool;
    var phi_787_: bool;
    var phi_788_: bool;
    var phi_821_: bool;
    var phi_863_: bool;

    mxc_texture_footprint = 1f;
    let _e265 = vPosition_1;
    g_2.P = _e265;
    let _e267 = vObjectPosition_1;
    g_2.Pobj = _e267;
    let _e269 = vNormal_1;
    param_241 = _e269;
    param_242 = vec3<f32>(0f, 0f, 1f);
    let _e270 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_241), (&param_242));
    N_2 = _e270;
    let _e271 = gl_FrontFacing_1;
    if !(_e271) {
        let _e273 = N_2;
        N_2 = -(_e273);
    }
    let _e276 = mxc_view.eye;
    let _e278 = vPosition_1;
    param_243 = (_e276.xyz - _e278);
    let _e280 = N_2;
    param_244 = _e280;
    let _e281 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_243), (&param_244));
    wo_16 = _e281;
    let _e282 = wo_16;
    let _e283 = N_2;
    facing = dot(_e282, _e283);
    let _e285 = facing;
    if (_e285 < 0.01f) {
        let _e287 = N_2;
        let _e288 = facing;
        let _e290 = wo_16;
        N_2 = normalize((_e287 + (_e290 * (0.01f - _e288))));
    }
    let _e295 = vTangent_1[3u];
    handedness = select(1f, -1f, (_e295 < 0f));
    let _e298 = N_2;
    param_245 = _e298;
    let _e299 = vTangent_1;
    param_246 = _e299.xyz;
    let _e301 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_245), (&param_246));
    frame_4 = _e301;
    let _e302 = N_2;
    g_2.N = _e302;
    let _e305 = frame_4[0];
    g_2.T = _e305;
    let _e308 = frame_4[1];
    let _e309 = handedness;
    g_2.B = (_e308 * _e309);
    let _e312 = vObjectNormal_1;
    param_247 = _e312;
    param_248 = vec3<f32>(0f, 0f, 1f);
    let _e313 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_247), (&param_248));
    g_2.Nobj = _e313;
    let _e316 = g_2.Nobj;
    param_249 = _e316;
    let _e317 = vObjectTangent_1;
    param_250 = _e317;
    let _e318 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_249), (&param_250));
    objectFrame = _e318;
    let _e320 = objectFrame[0];
    g_2.Tobj = _e320;
    let _e323 = objectFrame[1];
    let _e324 = handedness;
    g_2.Bobj = (_e323 * _e324);
    let _e327 = vUv_1;
    g_2.uv = _e327;
    g_2.color = vec4<f32>(1f, 1f, 1f, 1f);
    let _e331 = mxc_view.objectToWorld;
    g_2.objectToWorld = _e331;
    let _e334 = mxc_params.frame;
    g_2.frame = _e334;
    let _e337 = mxc_params.time;
    g_2.time = _e337;
    let _e341 = mxc_view.jitter[2u];
    mxc_texture_footprint = _e341;
    let _e342 = mxc_texture_footprint;
    if !((_e342 > 0f)) {
        mxc_texture_footprint = 1f;
    }
    let _e346 = gl_FragCoord_1[0u];
    let _e349 = gl_FragCoord_1[1u];
    let _e353 = mxc_view.counts[2u];
    param_251 = (bitcast<u32>(_e353) + 7u);
    let _e356 = mxc_pcg_u0028_u1_u003b((&param_251));
    param_252 = (u32(_e349) + _e356);
    let _e358 = mxc_pcg_u0028_u1_u003b((&param_252));
    param_253 = (u32(_e346) ^ _e358);
    let _e360 = mxc_pcg_u0028_u1_u003b((&param_253));
    param_254 = _e360;
    mxc_closure_seed_u0028_u1_u003b((&param_254));
    let _e361 = g_2;
    param_255 = _e361;
    let _e362 = wo_16;
    param_256 = _e362;
    mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b((&param_255), (&param_256), (&param_257));
    let _e363 = param_257;
    c_10 = _e363;
    let _e365 = c_10.emission;
    let _e368 = mxc_view.environment[1u];
    radiance = (_e365 * _e368);
    let _e370 = mxc_light_count_u0028_();
    lights = _e370;
    let _e371 = mxc_light_kinds_u0028_();
    kinds = _e371;
    let _e372 = mxc_environment_code_u0028_();
    image = (_e372 == 3i);
    let _e374 = mxc_environment_code_u0028_();
    if (_e374 != 0i) {
        let _e378 = mxc_view.counts[3u];
        local_23 = max(_e378, 1i);
    } else {
        local_23 = 0i;
    }
    let _e380 = local_23;
    n_1 = _e380;
    let _e382 = gl_FragCoord_1[0u];
    let _e385 = gl_FragCoord_1[1u];
    let _e389 = mxc_view.counts[2u];
    param_258 = bitcast<u32>(_e389);
    let _e391 = mxc_pcg_u0028_u1_u003b((&param_258));
    param_259 = (u32(_e385) + _e391);
    let _e393 = mxc_pcg_u0028_u1_u003b((&param_259));
    param_260 = (u32(_e382) + _e393);
    let _e395 = mxc_pcg_u0028_u1_u003b((&param_260));
    seed_2 = _e395;
    let _e397 = gl_FragCoord_1[0u];
    let _e400 = gl_FragCoord_1[1u];
    param_261 = (u32(_e400) + 2654435769u);
    let _e403 = mxc_pcg_u0028_u1_u003b((&param_261));
    param_262 = (u32(_e397) ^ _e403);
    let _e405 = mxc_pcg_u0028_u1_u003b((&param_262));
    pixel = _e405;
    let _e406 = pixel;
    param_263 = _e406;
    let _e407 = mxc_uniform_u0028_u1_u003b((&param_263));
    let _e408 = param_263;
    pixel = _e408;
    let _e409 = pixel;
    param_264 = _e409;
    let _e410 = mxc_uniform_u0028_u1_u003b((&param_264));
    let _e411 = param_264;
    pixel = _e411;
    let _e412 = pixel;
    param_265 = _e412;
    let _e413 = mxc_uniform_u0028_u1_u003b((&param_265));
    let _e414 = param_265;
    pixel = _e414;
    let _e415 = pixel;
    param_266 = _e415;
    let _e416 = mxc_uniform_u0028_u1_u003b((&param_266));
    let _e417 = param_266;
    pixel = _e417;
    shift = vec4<f32>(_e407, _e410, _e413, _e416);
    sum = vec3<f32>(0f, 0f, 0f);
    b_3 = 0i;
    loop {
        let _e419 = b_3;
        let _e420 = n_1;
        let _e421 = lights;
        if (_e419 < max(_e420, select(0i, 1i, (_e421 > 0i)))) {
            let _e426 = b_3;
            let _e428 = lights;
            batchLights = select(0i, _e428, (_e426 == 0i));
            let _e430 = b_3;
            let _e431 = n_1;
            if (_e430 < _e431) {
                let _e433 = image;
                local_24 = (1i + select(0i, 1i, _e433));
            } else {
                local_24 = 0i;
            }
            let _e436 = local_24;
            batchSamples = _e436;
            let _e439 = mxc_view.counts[2u];
            let _e441 = n_1;
            let _e445 = b_3;
            index = ((bitcast<u32>(_e439) * bitcast<u32>(max(_e441, 1i))) + bitcast<u32>(_e445));
            let _e448 = index;
            param_267 = _e448;
            param_268 = 2u;
            let _e449 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_267), (&param_268));
            let _e450 = index;
            param_269 = _e450;
            param_270 = 3u;
            let _e451 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_269), (&param_270));
            let _e452 = index;
            param_271 = _e452;
            param_272 = 5u;
            let _e453 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_271), (&param_272));
            let _e454 = index;
            param_273 = _e454;
            param_274 = 7u;
            let _e455 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_273), (&param_274));
            let _e457 = shift;
            choice = fract((vec4<f32>(_e449, _e451, _e453, _e455) + _e457));
            smp.valid = false;
            smp.evaluate = false;
            smp.delta = false;
            smp.pdf = 0f;
            smp.weight = vec3<f32>(0f, 0f, 0f);
            let _e465 = N_2;
            smp.wi = _e465;
            let _e467 = n_1;
            if (_e467 > 0i) {
                let _e470 = choice[2u];
                let _e472 = choice[3u];
                let _e474 = choice[0u];
                let _e476 = c_10;
                param_275 = _e476;
                let _e477 = wo_16;
                param_276 = _e477;
                param_277 = vec3<f32>(_e470, _e472, _e474);
                let _e478 = mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b((&param_275), (&param_276), (&param_277));
                smp = _e478;
            }
            let _e480 = smp.wi;
            let _e481 = N_2;
            above_4 = (dot(_e480, _e481) > 0f);
            let _e485 = smp.valid;
            if _e485 {
                let _e486 = above_4;
                if _e486 {
                    let _e488 = smp.wi;
                    local_26 = _e488;
                } else {
                    let _e489 = wo_16;
                    param_278 = -(_e489);
                    let _e492 = smp.wi;
                    param_279 = _e492;
                    let _e493 = mxc_exit_direction_u0028_vf3_u003b_vf3_u003b((&param_278), (&param_279));
                    local_26 = _e493;
                }
                let _e494 = local_26;
                param_280 = _e494;
                let _e495 = mxc_environment_u0028_vf3_u003b((&param_280));
                local_25 = _e495;
            } else {
                local_25 = vec3<f32>(0f, 0f, 0f);
            }
            let _e496 = local_25;
            seen = _e496;
            let _e497 = b_3;
            let _e498 = n_1;
            let _e501 = smp.valid;
            let _e502 = ((_e497 < _e498) && _e501);
            phi_657_ = _e502;
            if _e502 {
                let _e504 = smp.evaluate;
                phi_657_ = !(_e504);
            }
            let _e507 = phi_657_;
            if _e507 {
                let _e508 = image;
                let _e509 = above_4;
                let _e510 = (_e508 && _e509);
                phi_668_ = _e510;
                if _e510 {
                    let _e512 = smp.delta;
                    phi_668_ = !(_e512);
                }
                let _e515 = phi_668_;
                if _e515 {
                    let _e517 = smp.wi;
                    param_281 = _e517;
                    let _e520 = mxc_view.environment[2u];
                    param_282 = _e520;
                    let _e521 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_281), (&param_282));
                    param_283 = _e521;
                    let _e522 = mxc_env_pdf_u0028_vf3_u003b((&param_283));
                    let _e524 = smp.pdf;
                    param_284 = _e524;
                    param_285 = _e522;
                    let _e525 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_284), (&param_285));
                    local_27 = _e525;
                } else {
                    local_27 = 1f;
                }
                let _e526 = local_27;
                w_1 = _e526;
                let _e527 = w_1;
                let _e529 = smp.weight;
                let _e531 = seen;
                let _e533 = sum;
                sum = (_e533 + ((_e529 * _e527) * _e531));
            }
            m_5 = vec3<f32>(0f, 0f, 0f);
            lightPdf = 0f;
            let _e535 = N_2;
            imageWi = _e535;
            imageSeen = vec3<f32>(0f, 0f, 0f);
            let _e536 = image;
            let _e537 = b_3;
            let _e538 = n_1;
            if (_e536 && (_e537 < _e538)) {
                let _e542 = choice[1u];
                let _e543 = seed_2;
                param_286 = _e543;
                let _e544 = mxc_uniform_u0028_u1_u003b((&param_286));
                let _e545 = param_286;
                seed_2 = _e545;
                let _e546 = seed_2;
                param_287 = _e546;
                let _e547 = mxc_uniform_u0028_u1_u003b((&param_287));
                let _e548 = param_287;
                seed_2 = _e548;
                let _e549 = seed_2;
                param_288 = _e549;
                let _e550 = mxc_uniform_u0028_u1_u003b((&param_288));
                let _e551 = param_288;
                seed_2 = _e551;
                v_8 = vec4<f32>(_e542, _e544, _e547, _e550);
                let _e553 = v_8;
                param_289 = _e553;
                let _e554 = mxc_env_sample_u0028_vf4_u003b_f1_u003b((&param_289), (&param_290));
                let _e555 = param_290;
                lightPdf = _e555;
                m_5 = _e554;
                let _e556 = m_5;
                param_291 = _e556;
                let _e559 = mxc_view.environment[2u];
                param_292 = _e559;
                let _e560 = mxc_env_to_world_u0028_vf3_u003b_f1_u003b((&param_291), (&param_292));
                imageWi = _e560;
                let _e561 = lightPdf;
                let _e562 = (_e561 > 0f);
                phi_730_ = _e562;
                if _e562 {
                    let _e563 = imageWi;
                    let _e564 = N_2;
                    phi_730_ = (dot(_e563, _e564) > 0f);
                }
                let _e568 = phi_730_;
                if _e568 {
                    let _e569 = imageWi;
                    param_293 = _e569;
                    let _e570 = mxc_environment_u0028_vf3_u003b((&param_293));
                    imageSeen = _e570;
                }
            }
            j_2 = 0i;
            loop {
                let _e571 = j_2;
                let _e572 = batchLights;
                let _e573 = batchSamples;
                if (_e571 < (_e572 + _e573)) {
                    let _e576 = N_2;
                    wi_6 = _e576;
                    incoming = vec3<f32>(0f, 0f, 0f);
                    use_ = true;
                    let _e577 = n_1;
                    let _e579 = j_2;
                    let _e580 = batchLights;
                    if ((_e577 == 0i) || (_e579 < _e580)) {
                        local_28 = 0i;
                    } else {
                        let _e583 = j_2;
                        let _e584 = batchLights;
                        local_28 = select(2i, 1i, (_e583 == ((_e584 + 1i) - 1i)));
                    }
                    let _e589 = local_28;
                    strategy = _e589;
                    let _e590 = strategy;
                    if (_e590 == 0i) {
                        let _e592 = j_2;
                        let _e595 = mxc_view.lightVector[_e592];
                        light = _e595;
                        let _e596 = j_2;
                        let _e599 = mxc_view.lightRadiance[_e596];
                        incoming = _e599.xyz;
                        let _e601 = kinds;
                        let _e602 = (_e601 == 1i);
                        phi_788_ = _e602;
                        if !(_e602) {
                            let _e604 = kinds;
                            let _e606 = ((_e604 & 1i) != 0i);
                            phi_787_ = _e606;
                            if _e606 {
                                let _e608 = light[3u];
                                phi_787_ = (_e608 == 0f);
                            }
                            let _e611 = phi_787_;
                            phi_788_ = _e611;
                        }
                        let _e613 = phi_788_;
                        directional = _e613;
                        let _e614 = directional;
                        if _e614 {
                            let _e615 = light;
                            param_294 = _e615.xyz;
                            let _e617 = N_2;
                            param_295 = _e617;
                            let _e618 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_294), (&param_295));
                            wi_6 = _e618;
                        } else {
                            let _e619 = light;
                            let _e621 = vPosition_1;
                            d_8 = (_e619.xyz - _e621);
                            let _e623 = d_8;
                            let _e624 = d_8;
                            d2_ = max(dot(_e623, _e624), 0.00000001f);
                            let _e627 = d_8;
                            let _e628 = d2_;
                            wi_6 = (_e627 * inverseSqrt(_e628));
                            let _e631 = d2_;
                            let _e632 = incoming;
                            incoming = (_e632 / vec3(_e631));
                            let _e635 = kinds;
                            let _e637 = ((_e635 & 4i) != 0i);
                            phi_821_ = _e637;
                            if _e637 {
                                let _e639 = light[3u];
                                phi_821_ = (_e639 == 2f);
                            }
                            let _e642 = phi_821_;
                            if _e642 {
                                let _e643 = j_2;
                                let _e646 = mxc_view.lightSpot[_e643];
                                spot = _e646;
                                let _e648 = spot[3u];
                                let _e649 = j_2;
                                let _e653 = mxc_view.lightRadiance[_e649][3u];
                                let _e654 = wi_6;
                                let _e656 = spot;
                                let _e660 = incoming;
                                incoming = (_e660 * smoothstep(_e648, _e653, dot(-(_e654), _e656.xyz)));
                            }
                        }
                    } else {
                        let _e662 = strategy;
                        if (_e662 == 1i) {
                            let _e665 = smp.wi;
                            wi_6 = _e665;
                            let _e666 = seen;
                            incoming = _e666;
                            let _e668 = smp.valid;
                            let _e670 = smp.evaluate;
                            use_ = (_e668 && _e670);
                        } else {
                            let _e672 = imageWi;
                            wi_6 = _e672;
                            let _e673 = imageSeen;
                            incoming = _e673;
                            let _e674 = lightPdf;
                            let _e675 = (_e674 > 0f);
                            phi_863_ = _e675;
                            if _e675 {
                                let _e676 = imageWi;
                                let _e677 = N_2;
                                phi_863_ = (dot(_e676, _e677) > 0f);
                            }
                            let _e681 = phi_863_;
                            use_ = _e681;
                        }
                    }
                    let _e682 = strategy;
                    let _e684 = c_10;
                    param_296 = _e684;
                    let _e685 = wo_16;
                    param_297 = _e685;
                    let _e686 = wi_6;
                    param_298 = _e686;
                    param_299 = (_e682 != 0i);
                    let _e687 = mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b((&param_296), (&param_297), (&param_298), (&param_299), (&param_300));
                    let _e688 = param_300;
                    pdf_2 = _e688;
                    f_5 = _e687;
                    let _e689 = strategy;
                    if (_e689 == 0i) {
                        let _e691 = f_5;
                        let _e692 = incoming;
                        let _e694 = radiance;
                        radiance = (_e694 + (_e691 * _e692));
                    } else {
                        let _e696 = strategy;
                        if (_e696 == 1i) {
                            let _e698 = use_;
                            let _e699 = pdf_2;
                            if (_e698 && (_e699 > 0f)) {
                                let _e702 = image;
                                let _e703 = above_4;
                                if (_e702 && _e703) {
                                    let _e705 = wi_6;
                                    param_301 = _e705;
                                    let _e708 = mxc_view.environment[2u];
                                    param_302 = _e708;
                                    let _e709 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_301), (&param_302));
                                    param_303 = _e709;
                                    let _e710 = mxc_env_pdf_u0028_vf3_u003b((&param_303));
                                    let _e711 = pdf_2;
                                    param_304 = _e711;
                                    param_305 = _e710;
                                    let _e712 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_304), (&param_305));
                                    local_29 = _e712;
                                } else {
                                    local_29 = 1f;
                                }
                                let _e713 = local_29;
                                w_2 = _e713;
                                let _e714 = w_2;
                                let _e715 = f_5;
                                let _e717 = pdf_2;
                                let _e720 = incoming;
                                let _e722 = sum;
                                sum = (_e722 + (((_e715 * _e714) / vec3(_e717)) * _e720));
                            }
                        } else {
                            let _e724 = use_;
                            if _e724 {
                                let _e725 = m_5;
                                param_306 = _e725;
                                let _e726 = mxc_env_pdf_u0028_vf3_u003b((&param_306));
                                param_307 = _e726;
                                let _e727 = pdf_2;
                                param_308 = _e727;
                                let _e728 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_307), (&param_308));
                                w_3 = _e728;
                                let _e729 = w_3;
                                let _e730 = f_5;
                                let _e732 = incoming;
                                let _e734 = lightPdf;
                                let _e737 = sum;
                                sum = (_e737 + (((_e730 * _e729) * _e732) / vec3(_e734)));
                            }
                        }
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e739 = j_2;
                    j_2 = (_e739 + 1i);
                }
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e741 = b_3;
            b_3 = (_e741 + 1i);
        }
    }
    let _e743 = sum;
    let _e744 = n_1;
    let _e749 = radiance;
    radiance = (_e749 + (_e743 / vec3(f32(max(_e744, 1i)))));
    let _e752 = c_10.transparency;
    param_309 = _e752;
    let _e753 = mxc_luminance_u0028_vf3_u003b((&param_309));
    coverage = (1f - clamp(_e753, 0f, 1f));
    let _e756 = radiance;
    let _e757 = coverage;
    outColor = vec4<f32>(_e756.x, _e756.y, _e756.z, _e757);
    return;
}

@fragment 
fn main(@location(0) vPosition: vec3<f32>, @location(4) vObjectPosition: vec3<f32>, @location(1) vNormal: vec3<f32>, @builtin(front_facing) gl_FrontFacing: bool, @location(2) vTangent: vec4<f32>, @location(5) vObjectNormal: vec3<f32>, @location(6) vObjectTangent: vec3<f32>, @location(3) vUv: vec2<f32>, @builtin(position) gl_FragCoord: vec4<f32>) -> @location(0) vec4<f32> {
    vPosition_1 = vPosition;
    vObjectPosition_1 = vObjectPosition;
    vNormal_1 = vNormal;
    gl_FrontFacing_1 = gl_FrontFacing;
    vTangent_1 = vTangent;
    vObjectNormal_1 = vObjectNormal;
    vObjectTangent_1 = vObjectTangent;
    vUv_1 = vUv;
    gl_FragCoord_1 = gl_FragCoord;
    main_1();
    let _e19 = outColor;
    return _e19;
}
// ==== vertex (main) ====
struct MxcView {
    objectToWorld: mat4x4<f32>,
    normalToWorld: mat4x4<f32>,
    worldToClip: mat4x4<f32>,
    eye: vec4<f32>,
    jitter: vec4<f32>,
    lightVector: array<vec4<f32>, 8>,
    lightSpot: array<vec4<f32>, 8>,
    lightRadiance: array<vec4<f32>, 8>,
    counts: vec4<i32>,
    environment: vec4<f32>,
}

struct gl_PerVertex {
    @builtin(position) gl_Position: vec4<f32>,
    gl_PointSize: f32,
    gl_ClipDistance: array<f32, 1>,
}

struct VertexOutput {
    @location(0) member: vec3<f32>,
    @location(1) member_1: vec3<f32>,
    @location(2) member_2: vec4<f32>,
    @location(3) member_3: vec2<f32>,
    @location(4) member_4: vec3<f32>,
    @location(5) member_5: vec3<f32>,
    @location(6) member_6: vec3<f32>,
    @builtin(position) gl_Position: vec4<f32>,
}

const MXC_ENVIRONMENT: i32 = -1i;
const MXC_LIGHT_COUNT: i32 = -1i;
const MXC_LIGHT_KINDS: i32 = -1i;

@group(0) @binding(1) 
var<uniform> mxc_view: MxcView;
var<private> inPosition_1: vec3<f32>;
var<private> vPosition: vec3<f32>;
var<private> vNormal: vec3<f32>;
var<private> inNormal_1: vec3<f32>;
var<private> vTangent: vec4<f32>;
var<private> inTangent_1: vec4<f32>;
var<private> vUv: vec2<f32>;
var<private> inUv_1: vec2<f32>;
var<private> vObjectPosition: vec3<f32>;
var<private> vObjectNormal: vec3<f32>;
var<private> vObjectTangent: vec3<f32>;
var<private> unnamed: gl_PerVertex = gl_PerVertex(vec4<f32>(0f, 0f, 0f, 1f), 1f, array<f32, 1>());

fn main_1() {
    var world: vec4<f32>;
    var clip: vec4<f32>;

    let _e31 = mxc_view.objectToWorld;
    let _e32 = inPosition_1;
    world = (_e31 * vec4<f32>(_e32.x, _e32.y, _e32.z, 1f));
    let _e38 = world;
    vPosition = _e38.xyz;
    let _e41 = mxc_view.normalToWorld;
    let _e49 = inNormal_1;
    vNormal = (mat3x3<f32>(_e41[0].xyz, _e41[1].xyz, _e41[2].xyz) * _e49);
    let _e52 = mxc_view.objectToWorld;
    let _e60 = inTangent_1;
    let _e62 = (mat3x3<f32>(_e52[0].xyz, _e52[1].xyz, _e52[2].xyz) * _e60.xyz);
    let _e64 = inTangent_1[3u];
    vTangent = vec4<f32>(_e62.x, _e62.y, _e62.z, _e64);
    let _e69 = inUv_1;
    vUv = _e69;
    let _e70 = inPosition_1;
    vObjectPosition = _e70;
    let _e71 = inNormal_1;
    vObjectNormal = _e71;
    let _e72 = inTangent_1;
    vObjectTangent = _e72.xyz;
    let _e75 = mxc_view.worldToClip;
    let _e76 = world;
    clip = (_e75 * _e76);
    let _e79 = mxc_view.jitter;
    let _e82 = clip[3u];
    let _e84 = clip;
    let _e86 = (_e84.xy + (_e79.xy * _e82));
    clip[0u] = _e86.x;
    clip[1u] = _e86.y;
    let _e91 = clip;
    unnamed.gl_Position = _e91;
    return;
}

@vertex 
fn main(@location(0) inPosition: vec3<f32>, @location(1) inNormal: vec3<f32>, @location(2) inTangent: vec4<f32>, @location(3) inUv: vec2<f32>) -> VertexOutput {
    inPosition_1 = inPosition;
    inNormal_1 = inNormal;
    inTangent_1 = inTangent;
    inUv_1 = inUv;
    main_1();
    let _e18 = unnamed.gl_Position.y;
    unnamed.gl_Position.y = -(_e18);
    let _e20 = vPosition;
    let _e21 = vNormal;
    let _e22 = vTangent;
    let _e23 = vUv;
    let _e24 = vObjectPosition;
    let _e25 = vObjectNormal;
    let _e26 = vObjectTangent;
    let _e27 = unnamed.gl_Position;
    return VertexOutput(_e20, _e21, _e22, _e23, _e24, _e25, _e26, _e27);
}
