// ==== corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx: material Default, placements ====
// mxc_tables {"binding":0,"group":0,"samplerBinding":512}
// MxcView {"binding":1,"group":0}
// MxcParameters {"binding":2,"group":0}
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
    msT: array<f32, 2>,
    msLobe: array<vec3<f32>, 2>,
    msLobeT: array<vec3<f32>, 2>,
    msPick: array<f32, 2>,
    msSplit: array<f32, 2>,
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
@group(1) @binding(0) 
var mxc_env_radiance_texture: texture_2d<f32>;
@group(1) @binding(512) 
var mxc_env_radiance_sampler: sampler;
@group(1) @binding(1) 
var<storage, read_write> unnamed: MxcEnvDistribution;

fn mxc_luminance_u0028_vf3_u003b(c: ptr<function, vec3<f32>>) -> f32 {
    let _e125 = (*c);
    return dot(_e125, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b(l: ptr<function, MxcLobe>, mu: ptr<function, f32>) -> vec3<f32> {
    return vec3<f32>(1f, 1f, 1f);
}

fn mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_1: ptr<function, MxcLobe>) -> bool {
    return false;
}

fn mxc_mean_u0028_vf3_u003b(c_1: ptr<function, vec3<f32>>) -> f32 {
    let _e126 = (*c_1)[0u];
    let _e128 = (*c_1)[1u];
    let _e131 = (*c_1)[2u];
    return (((_e126 + _e128) + _e131) * 0.33333334f);
}

fn mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b(cosi: ptr<function, f32>, eta: ptr<function, f32>) -> f32 {
    var sin2t: f32;
    var cost: f32;
    var rs: f32;
    var rp: f32;

    let _e130 = (*eta);
    if (abs((_e130 - 1f)) < 0.000001f) {
        return 0f;
    }
    let _e134 = (*cosi);
    let _e135 = (*cosi);
    let _e138 = (*eta);
    let _e139 = (*eta);
    sin2t = ((1f - (_e134 * _e135)) / (_e138 * _e139));
    let _e142 = sin2t;
    if (_e142 >= 1f) {
        return 1f;
    }
    let _e144 = sin2t;
    cost = sqrt((1f - _e144));
    let _e147 = (*cosi);
    let _e148 = (*eta);
    let _e149 = cost;
    let _e152 = (*cosi);
    let _e153 = (*eta);
    let _e154 = cost;
    rs = ((_e147 - (_e148 * _e149)) / (_e152 + (_e153 * _e154)));
    let _e158 = (*eta);
    let _e159 = (*cosi);
    let _e161 = cost;
    let _e163 = (*eta);
    let _e164 = (*cosi);
    let _e166 = cost;
    rp = (((_e158 * _e159) - _e161) / ((_e163 * _e164) + _e166));
    let _e169 = rs;
    let _e170 = rs;
    let _e172 = rp;
    let _e173 = rp;
    return (0.5f * ((_e169 * _e170) + (_e172 * _e173)));
}

fn mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_2: ptr<function, MxcLobe>, above: ptr<function, bool>) -> f32 {
    var local: f32;

    let _e127 = (*above);
    if _e127 {
        let _e129 = (*l_2).eta;
        local = _e129;
    } else {
        let _e131 = (*l_2).eta;
        local = (1f / _e131);
    }
    let _e133 = local;
    return _e133;
}

fn mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b(l_3: ptr<function, MxcLobe>, cosh_: ptr<function, f32>, above_1: ptr<function, bool>) -> vec3<f32> {
    var f: vec3<f32>;
    var param: MxcLobe;
    var param_1: bool;
    var param_2: f32;
    var param_3: f32;

    f = vec3<f32>(1f, 1f, 1f);
    let _e133 = (*l_3).kind;
    if (_e133 == 1i) {
        let _e135 = (*l_3);
        param = _e135;
        let _e136 = (*above_1);
        param_1 = _e136;
        let _e137 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param), (&param_1));
        let _e138 = (*cosh_);
        param_2 = _e138;
        param_3 = _e137;
        let _e139 = mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b((&param_2), (&param_3));
        f = vec3(_e139);
    }
    let _e141 = f;
    return _e141;
}

fn mxc_rough_alpha_u0028_vf2_u003b(alpha: ptr<function, vec2<f32>>) -> vec2<f32> {
    let _e125 = (*alpha);
    return max(_e125, vec2<f32>(0.0001f, 0.0001f));
}

fn mxc_ggx_d_u0028_vf3_u003b_vf2_u003b(m: ptr<function, vec3<f32>>, alpha_1: ptr<function, vec2<f32>>) -> f32 {
    var param_4: vec2<f32>;
    var s: vec3<f32>;
    var d: f32;

    let _e130 = (*m)[2u];
    if (_e130 <= 0f) {
        return 0f;
    }
    let _e132 = (*alpha_1);
    param_4 = _e132;
    let _e133 = mxc_rough_alpha_u0028_vf2_u003b((&param_4));
    (*alpha_1) = _e133;
    let _e135 = (*m)[0u];
    let _e137 = (*alpha_1)[0u];
    let _e140 = (*m)[1u];
    let _e142 = (*alpha_1)[1u];
    let _e145 = (*m)[2u];
    s = vec3<f32>((_e135 / _e137), (_e140 / _e142), _e145);
    let _e147 = s;
    let _e148 = s;
    d = dot(_e147, _e148);
    let _e151 = (*alpha_1)[0u];
    let _e154 = (*alpha_1)[1u];
    let _e156 = d;
    let _e158 = d;
    return (1f / ((((3.1415927f * _e151) * _e154) * _e156) * _e158));
}

fn mxc_sqr_u0028_f1_u003b(x: ptr<function, f32>) -> f32 {
    let _e125 = (*x);
    let _e126 = (*x);
    return (_e125 * _e126);
}

fn mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b(v: ptr<function, vec3<f32>>, alpha_2: ptr<function, vec2<f32>>) -> f32 {
    var param_5: vec2<f32>;
    var z2_: f32;
    var a2_: f32;
    var param_6: f32;
    var param_7: f32;

    let _e131 = (*alpha_2);
    param_5 = _e131;
    let _e132 = mxc_rough_alpha_u0028_vf2_u003b((&param_5));
    (*alpha_2) = _e132;
    let _e134 = (*v)[2u];
    let _e136 = (*v)[2u];
    z2_ = (_e134 * _e136);
    let _e138 = z2_;
    if (_e138 <= 0f) {
        return 10000000000f;
    }
    let _e141 = (*alpha_2)[0u];
    let _e143 = (*v)[0u];
    param_6 = (_e141 * _e143);
    let _e145 = mxc_sqr_u0028_f1_u003b((&param_6));
    let _e147 = (*alpha_2)[1u];
    let _e149 = (*v)[1u];
    param_7 = (_e147 * _e149);
    let _e151 = mxc_sqr_u0028_f1_u003b((&param_7));
    let _e153 = z2_;
    a2_ = ((_e145 + _e151) / _e153);
    let _e155 = a2_;
    return (0.5f * (-1f + sqrt((1f + _e155))));
}

fn mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b(v_1: ptr<function, vec3<f32>>, alpha_3: ptr<function, vec2<f32>>) -> f32 {
    var param_8: vec3<f32>;
    var param_9: vec2<f32>;

    let _e128 = (*v_1);
    param_8 = _e128;
    let _e129 = (*alpha_3);
    param_9 = _e129;
    let _e130 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_8), (&param_9));
    return (1f / (1f + _e130));
}

fn mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo: ptr<function, vec3<f32>>, m_1: ptr<function, vec3<f32>>, alpha_4: ptr<function, vec2<f32>>) -> f32 {
    var param_10: vec3<f32>;
    var param_11: vec2<f32>;
    var param_12: vec3<f32>;
    var param_13: vec2<f32>;

    let _e132 = (*wo)[2u];
    if (_e132 <= 0f) {
        return 0f;
    }
    let _e134 = (*wo);
    param_10 = _e134;
    let _e135 = (*alpha_4);
    param_11 = _e135;
    let _e136 = mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b((&param_10), (&param_11));
    let _e137 = (*wo);
    let _e138 = (*m_1);
    let _e142 = (*m_1);
    param_12 = _e142;
    let _e143 = (*alpha_4);
    param_13 = _e143;
    let _e144 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_12), (&param_13));
    let _e147 = (*wo)[2u];
    return (((_e136 * max(dot(_e137, _e138), 0f)) * _e144) / _e147);
}

fn mxc_is_delta_u0028_vf2_u003b(alpha_5: ptr<function, vec2<f32>>) -> bool {
    let _e126 = (*alpha_5)[0u];
    let _e128 = (*alpha_5)[1u];
    return (max(_e126, _e128) < 0.0001f);
}

fn mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_4: ptr<function, MxcLobe>, wo_1: ptr<function, vec3<f32>>, wi: ptr<function, vec3<f32>>) -> f32 {
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
    var phi_2675_: bool;
    var phi_2756_: bool;

    let _e146 = (*l_4).kind;
    switch _e146 {
        case 2, 3, 1: {
            let _e160 = (*l_4).alpha;
            param_14 = _e160;
            let _e161 = mxc_is_delta_u0028_vf2_u003b((&param_14));
            if _e161 {
                return 0f;
            }
            let _e163 = (*wo_1)[2u];
            above_2 = (_e163 > 0f);
            let _e165 = above_2;
            if _e165 {
                let _e166 = (*wo_1);
                local_1 = _e166;
            } else {
                let _e167 = (*wo_1);
                local_1 = -(_e167);
            }
            let _e169 = local_1;
            o = _e169;
            let _e170 = above_2;
            if _e170 {
                let _e171 = (*wi);
                local_2 = _e171;
            } else {
                let _e172 = (*wi);
                local_2 = -(_e172);
            }
            let _e174 = local_2;
            i = _e174;
            let _e176 = i[2u];
            if (_e176 > 0f) {
                let _e178 = o;
                let _e179 = i;
                h = normalize((_e178 + _e179));
                let _e182 = o;
                param_15 = _e182;
                let _e183 = h;
                param_16 = _e183;
                let _e185 = (*l_4).alpha;
                param_17 = _e185;
                let _e186 = mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_15), (&param_16), (&param_17));
                let _e187 = o;
                let _e188 = h;
                p = (_e186 / (4f * max(dot(_e187, _e188), 0.000001f)));
                let _e194 = (*l_4).kind;
                if (_e194 == 2i) {
                    let _e196 = p;
                    return _e196;
                }
                let _e198 = (*l_4).mode;
                if ((_e198 & 1i) == 0i) {
                    return 0f;
                }
                let _e201 = o;
                let _e202 = h;
                let _e205 = (*l_4);
                param_18 = _e205;
                param_19 = max(dot(_e201, _e202), 0f);
                let _e206 = above_2;
                param_20 = _e206;
                let _e207 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_18), (&param_19), (&param_20));
                param_21 = _e207;
                let _e208 = mxc_mean_u0028_vf3_u003b((&param_21));
                fr = _e208;
                let _e209 = p;
                let _e210 = (*l_4);
                param_22 = _e210;
                let _e211 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_22));
                phi_2756_ = _e211;
                if _e211 {
                    let _e213 = (*l_4).mode;
                    phi_2756_ = ((_e213 & 1i) != 0i);
                }
                let _e217 = phi_2756_;
                let _e218 = fr;
                return (_e209 * select(1f, _e218, _e217));
            }
            return 0f;
        }
        default: {
            let _e148 = (*wo_1)[2u];
            let _e149 = (_e148 > 0f);
            phi_2675_ = _e149;
            if _e149 {
                let _e151 = (*wi)[2u];
                phi_2675_ = (_e151 > 0f);
            }
            let _e154 = phi_2675_;
            if _e154 {
                let _e156 = (*wi)[2u];
                local_3 = (_e156 * 0.31830987f);
            } else {
                local_3 = 0f;
            }
            let _e158 = local_3;
            return _e158;
        }
    }
}

fn mxc_safe_sqrt_u0028_f1_u003b(x_1: ptr<function, f32>) -> f32 {
    let _e125 = (*x_1);
    return sqrt(max(_e125, 0f));
}

fn mxc_fon_albedo_u0028_f1_u003b_f1_u003b(sigma: ptr<function, f32>, mu_1: ptr<function, f32>) -> f32 {
    var a: f32;
    var c_2: f32;
    var s_1: f32;
    var param_23: f32;
    var theta: f32;
    var tail: f32;
    var local_4: f32;
    var g: f32;

    let _e134 = (*sigma);
    a = (1f / (1f + (0.2877934f * _e134)));
    let _e138 = (*mu_1);
    c_2 = clamp(_e138, 0f, 1f);
    let _e140 = c_2;
    let _e141 = c_2;
    param_23 = (1f - (_e140 * _e141));
    let _e144 = mxc_safe_sqrt_u0028_f1_u003b((&param_23));
    s_1 = _e144;
    let _e145 = c_2;
    theta = acos(_e145);
    let _e147 = c_2;
    if (_e147 > 0.0001f) {
        let _e149 = s_1;
        let _e150 = s_1;
        let _e152 = s_1;
        let _e155 = c_2;
        local_4 = ((1f - ((_e149 * _e150) * _e152)) / _e155);
    } else {
        let _e157 = c_2;
        local_4 = (1.5f * _e157);
    }
    let _e159 = local_4;
    tail = _e159;
    let _e160 = s_1;
    let _e161 = theta;
    let _e162 = s_1;
    let _e163 = c_2;
    let _e167 = s_1;
    let _e169 = tail;
    let _e172 = s_1;
    g = (((_e160 * (_e161 - (_e162 * _e163))) + ((0.6666667f * _e167) * _e169)) - (0.6666667f * _e172));
    let _e175 = a;
    let _e176 = (*sigma);
    let _e177 = a;
    let _e179 = g;
    return (_e175 + (((_e176 * _e177) * _e179) * 0.31830987f));
}

fn mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b(sigma_1: ptr<function, f32>, wo_2: ptr<function, vec3<f32>>, wi_1: ptr<function, vec3<f32>>) -> f32 {
    var a_1: f32;
    var s_2: f32;
    var t: f32;
    var local_5: f32;

    let _e131 = (*sigma_1);
    a_1 = (1f / (1f + (0.2877934f * _e131)));
    let _e135 = (*wi_1);
    let _e136 = (*wo_2);
    let _e139 = (*wi_1)[2u];
    let _e141 = (*wo_2)[2u];
    s_2 = (dot(_e135, _e136) - (_e139 * _e141));
    let _e144 = s_2;
    if (_e144 > 0f) {
        let _e147 = (*wi_1)[2u];
        let _e149 = (*wo_2)[2u];
        local_5 = max(max(_e147, _e149), 0.000001f);
    } else {
        local_5 = 1f;
    }
    let _e152 = local_5;
    t = _e152;
    let _e153 = a_1;
    let _e154 = (*sigma_1);
    let _e155 = a_1;
    let _e157 = s_2;
    let _e159 = t;
    return ((_e153 + (((_e154 * _e155) * _e157) / _e159)) * 0.31830987f);
}

fn mxc_eon_u0028_vf3_u003b_f1_u003b_vf3_u003b_vf3_u003b(rho: ptr<function, vec3<f32>>, sigma_2: ptr<function, f32>, wo_3: ptr<function, vec3<f32>>, wi_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var f_1: vec3<f32>;
    var param_24: f32;
    var param_25: vec3<f32>;
    var param_26: vec3<f32>;
    var a_2: f32;
    var eavg: f32;
    var rhoMs: vec3<f32>;
    var param_27: f32;
    var param_28: f32;
    var param_29: f32;
    var param_30: f32;

    let _e139 = (*rho);
    let _e140 = (*sigma_2);
    param_24 = _e140;
    let _e141 = (*wo_3);
    param_25 = _e141;
    let _e142 = (*wi_2);
    param_26 = _e142;
    let _e143 = mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b((&param_24), (&param_25), (&param_26));
    f_1 = (_e139 * _e143);
    let _e145 = (*sigma_2);
    a_2 = (1f / (1f + (0.2877934f * _e145)));
    let _e149 = a_2;
    let _e150 = (*sigma_2);
    eavg = (_e149 * (1f + (0.07248821f * _e150)));
    let _e154 = eavg;
    if (_e154 < 0.999999f) {
        let _e156 = (*rho);
        let _e157 = (*rho);
        let _e159 = eavg;
        let _e161 = eavg;
        let _e165 = (*rho);
        let _e166 = eavg;
        rhoMs = ((((_e156 * _e157) * _e159) / vec3((1f - _e161))) / (vec3(1f) - (_e165 * (1f - _e166))));
        let _e172 = rhoMs;
        let _e173 = (*sigma_2);
        param_27 = _e173;
        let _e175 = (*wi_2)[2u];
        param_28 = _e175;
        let _e176 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_27), (&param_28));
        let _e179 = (*sigma_2);
        param_29 = _e179;
        let _e181 = (*wo_3)[2u];
        param_30 = _e181;
        let _e182 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_29), (&param_30));
        let _e186 = f_1;
        f_1 = (_e186 + (((_e172 * (1f - _e176)) * (1f - _e182)) * 0.31830987f));
    }
    let _e188 = f_1;
    return _e188;
}

fn mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo_4: ptr<function, vec3<f32>>, wi_3: ptr<function, vec3<f32>>, alpha_6: ptr<function, vec2<f32>>) -> f32 {
    var param_31: vec3<f32>;
    var param_32: vec2<f32>;
    var param_33: vec3<f32>;
    var param_34: vec2<f32>;

    let _e131 = (*wo_4);
    param_31 = _e131;
    let _e132 = (*alpha_6);
    param_32 = _e132;
    let _e133 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_31), (&param_32));
    let _e135 = (*wi_3);
    param_33 = _e135;
    let _e136 = (*alpha_6);
    param_34 = _e136;
    let _e137 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_33), (&param_34));
    return (1f / ((1f + _e133) + _e137));
}

fn mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_5: ptr<function, MxcLobe>, wo_5: ptr<function, vec3<f32>>, wi_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_35: vec2<f32>;
    var h_1: vec3<f32>;
    var f_2: vec3<f32>;
    var param_36: MxcLobe;
    var param_37: f32;
    var param_38: bool;
    var param_39: vec3<f32>;
    var param_40: vec2<f32>;
    var param_41: vec3<f32>;
    var param_42: vec3<f32>;
    var param_43: vec2<f32>;
    var phi_1790_: bool;
    var phi_1797_: bool;

    let _e139 = (*wo_5)[2u];
    let _e140 = (_e139 <= 0f);
    phi_1790_ = _e140;
    if !(_e140) {
        let _e143 = (*wi_4)[2u];
        phi_1790_ = (_e143 <= 0f);
    }
    let _e146 = phi_1790_;
    phi_1797_ = _e146;
    if !(_e146) {
        let _e149 = (*l_5).alpha;
        param_35 = _e149;
        let _e150 = mxc_is_delta_u0028_vf2_u003b((&param_35));
        phi_1797_ = _e150;
    }
    let _e152 = phi_1797_;
    if _e152 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e153 = (*wo_5);
    let _e154 = (*wi_4);
    h_1 = normalize((_e153 + _e154));
    let _e157 = (*wo_5);
    let _e158 = h_1;
    let _e161 = (*l_5);
    param_36 = _e161;
    param_37 = max(dot(_e157, _e158), 0f);
    param_38 = true;
    let _e162 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_36), (&param_37), (&param_38));
    f_2 = _e162;
    let _e164 = (*l_5).kind;
    if (_e164 == 1i) {
        let _e167 = (*l_5).c0_;
        let _e168 = f_2;
        f_2 = (_e168 * _e167);
    }
    let _e170 = f_2;
    let _e171 = h_1;
    param_39 = _e171;
    let _e173 = (*l_5).alpha;
    param_40 = _e173;
    let _e174 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_39), (&param_40));
    let _e176 = (*wo_5);
    param_41 = _e176;
    let _e177 = (*wi_4);
    param_42 = _e177;
    let _e179 = (*l_5).alpha;
    param_43 = _e179;
    let _e180 = mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_41), (&param_42), (&param_43));
    let _e183 = (*wo_5)[2u];
    return (((_e170 * _e174) * _e180) / vec3((4f * _e183)));
}

fn mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_6: ptr<function, MxcLobe>, wo_6: ptr<function, vec3<f32>>, wi_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var m_2: MxcLobe;
    var param_44: MxcLobe;
    var param_45: vec3<f32>;
    var param_46: vec3<f32>;
    var param_47: MxcLobe;
    var param_48: vec3<f32>;
    var param_49: vec3<f32>;
    var param_50: MxcLobe;
    var param_51: vec3<f32>;
    var param_52: vec3<f32>;
    var local_6: vec3<f32>;
    var param_53: vec3<f32>;
    var param_54: f32;
    var param_55: vec3<f32>;
    var param_56: vec3<f32>;
    var phi_2609_: bool;
    var phi_2624_: bool;

    let _e143 = (*l_6).kind;
    switch _e143 {
        case 1: {
            let _e145 = (*wo_6)[2u];
            let _e147 = (*wi_5)[2u];
            if ((_e145 * _e147) > 0f) {
                let _e151 = (*l_6).mode;
                if ((_e151 & 1i) == 0i) {
                    return vec3<f32>(0f, 0f, 0f);
                }
                let _e155 = (*wo_6)[2u];
                if (_e155 < 0f) {
                    let _e157 = (*l_6);
                    m_2 = _e157;
                    let _e159 = (*l_6).eta;
                    m_2.eta = (1f / _e159);
                    m_2.c0_ = vec3<f32>(1f, 1f, 1f);
                    let _e163 = (*wo_6);
                    let _e165 = (*wi_5);
                    let _e167 = m_2;
                    param_44 = _e167;
                    param_45 = -(_e163);
                    param_46 = -(_e165);
                    let _e168 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_44), (&param_45), (&param_46));
                    return _e168;
                }
                let _e169 = (*l_6);
                param_47 = _e169;
                let _e170 = (*wo_6);
                param_48 = _e170;
                let _e171 = (*wi_5);
                param_49 = _e171;
                let _e172 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_47), (&param_48), (&param_49));
                return _e172;
            }
            return vec3<f32>(0f, 0f, 0f);
        }
        case 3, 2: {
            let _e174 = (*l_6).kind;
            let _e175 = (_e174 == 3i);
            phi_2609_ = _e175;
            if _e175 {
                let _e177 = (*l_6).mode;
                phi_2609_ = ((_e177 & 1i) == 0i);
            }
            let _e181 = phi_2609_;
            if _e181 {
                return vec3<f32>(0f, 0f, 0f);
            }
            let _e182 = (*l_6);
            param_50 = _e182;
            let _e183 = (*wo_6);
            param_51 = _e183;
            let _e184 = (*wi_5);
            param_52 = _e184;
            let _e185 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_50), (&param_51), (&param_52));
            return _e185;
        }
        case 5: {
            let _e187 = (*wo_6)[2u];
            let _e188 = (_e187 > 0f);
            phi_2624_ = _e188;
            if _e188 {
                let _e190 = (*wi_5)[2u];
                phi_2624_ = (_e190 > 0f);
            }
            let _e193 = phi_2624_;
            if _e193 {
                let _e195 = (*l_6).c0_;
                param_53 = _e195;
                let _e197 = (*l_6).p0_;
                param_54 = _e197;
                let _e198 = (*wo_6);
                param_55 = _e198;
                let _e199 = (*wi_5);
                param_56 = _e199;
                let _e200 = mxc_eon_u0028_vf3_u003b_f1_u003b_vf3_u003b_vf3_u003b((&param_53), (&param_54), (&param_55), (&param_56));
                let _e202 = (*wi_5)[2u];
                local_6 = (_e200 * _e202);
            } else {
                local_6 = vec3<f32>(0f, 0f, 0f);
            }
            let _e204 = local_6;
            return _e204;
        }
        default: {
            return vec3<f32>(0f, 0f, 0f);
        }
    }
}

fn mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_7: ptr<function, MxcLobe>, transmitted: ptr<function, bool>) -> MxcLobe {
    var m_3: MxcLobe;
    var local_7: i32;

    let _e128 = (*l_7);
    m_3 = _e128;
    let _e130 = (*l_7).alpha;
    let _e131 = (*transmitted);
    m_3.alpha = min((_e130 * select(1.5f, 3f, _e131)), vec2<f32>(1f, 1f));
    let _e136 = (*transmitted);
    if _e136 {
        let _e138 = (*l_7).mode;
        local_7 = (_e138 & -2i);
    } else {
        let _e141 = (*l_7).mode;
        local_7 = (_e141 & -3i);
    }
    let _e143 = local_7;
    m_3.mode = _e143;
    let _e146 = (*l_7).kind;
    if (_e146 == 1i) {
        m_3.c0_ = vec3<f32>(1f, 1f, 1f);
        m_3.c1_ = vec3<f32>(1f, 1f, 1f);
    }
    let _e150 = m_3;
    return _e150;
}

fn mxc_to_local_u0028_mf33_u003b_vf3_u003b(frame: ptr<function, mat3x3<f32>>, v_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e126 = (*v_2);
    let _e128 = (*frame)[0];
    let _e130 = (*v_2);
    let _e132 = (*frame)[1];
    let _e134 = (*v_2);
    let _e136 = (*frame)[2];
    return vec3<f32>(dot(_e126, _e128), dot(_e130, _e132), dot(_e134, _e136));
}

fn mxc_frame_u0028_vf3_u003b_vf3_u003b(N: ptr<function, vec3<f32>>, T: ptr<function, vec3<f32>>) -> mat3x3<f32> {
    var t_1: vec3<f32>;
    var l2_: f32;
    var s_3: f32;
    var a_3: f32;
    var b: f32;

    let _e131 = (*T);
    let _e132 = (*N);
    let _e133 = (*N);
    let _e134 = (*T);
    t_1 = (_e131 - (_e132 * dot(_e133, _e134)));
    let _e138 = t_1;
    let _e139 = t_1;
    l2_ = dot(_e138, _e139);
    let _e141 = l2_;
    if !((_e141 > 0.000000000001f)) {
        let _e145 = (*N)[2u];
        s_3 = select(-1f, 1f, (_e145 >= 0f));
        let _e148 = s_3;
        let _e150 = (*N)[2u];
        a_3 = (-1f / (_e148 + _e150));
        let _e154 = (*N)[0u];
        let _e156 = (*N)[1u];
        let _e158 = a_3;
        b = ((_e154 * _e156) * _e158);
        let _e160 = s_3;
        let _e162 = (*N)[0u];
        let _e165 = (*N)[0u];
        let _e167 = a_3;
        let _e170 = s_3;
        let _e171 = b;
        let _e173 = s_3;
        let _e176 = (*N)[0u];
        t_1 = vec3<f32>((1f + (((_e160 * _e162) * _e165) * _e167)), (_e170 * _e171), (-(_e173) * _e176));
    } else {
        let _e179 = l2_;
        let _e181 = t_1;
        t_1 = (_e181 * inverseSqrt(_e179));
    }
    let _e183 = t_1;
    let _e184 = (*N);
    let _e185 = t_1;
    let _e186 = cross(_e184, _e185);
    let _e187 = (*N);
    return mat3x3<f32>(vec3<f32>(_e183.x, _e183.y, _e183.z), vec3<f32>(_e186.x, _e186.y, _e186.z), vec3<f32>(_e187.x, _e187.y, _e187.z));
}

fn mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b(c_3: ptr<function, MxcClosure>, wo_7: ptr<function, vec3<f32>>, wi_6: ptr<function, vec3<f32>>, wantPdf: ptr<function, bool>, pdf: ptr<function, f32>) -> vec3<f32> {
    var f_3: vec3<f32>;
    var p_1: f32;
    var k: i32;
    var l_8: MxcLobe;
    var frame_1: mat3x3<f32>;
    var param_57: vec3<f32>;
    var param_58: vec3<f32>;
    var o_1: vec3<f32>;
    var param_59: mat3x3<f32>;
    var param_60: vec3<f32>;
    var i_1: vec3<f32>;
    var param_61: mat3x3<f32>;
    var param_62: vec3<f32>;
    var fk: vec3<f32>;
    var pk: f32;
    var passes: i32;
    var pass_: i32;
    var shaped: bool;
    var m_4: MxcLobe;
    var local_8: MxcLobe;
    var param_63: MxcLobe;
    var param_64: bool;
    var scale: vec3<f32>;
    var local_9: vec3<f32>;
    var local_10: vec3<f32>;
    var local_11: vec3<f32>;
    var param_65: MxcLobe;
    var param_66: vec3<f32>;
    var param_67: vec3<f32>;
    var share: f32;
    var local_12: f32;
    var local_13: f32;
    var param_68: MxcLobe;
    var param_69: vec3<f32>;
    var param_70: vec3<f32>;
    var param_71: MxcLobe;
    var param_72: f32;
    var local_14: f32;

    f_3 = vec3<f32>(0f, 0f, 0f);
    p_1 = 0f;
    k = 0i;
    loop {
        let _e167 = k;
        let _e169 = (*c_3).count;
        if (_e167 < _e169) {
            let _e171 = k;
            let _e174 = (*c_3).lobes[_e171];
            l_8 = _e174;
            let _e176 = l_8.weight;
            if all((_e176 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e180 = l_8.N;
            param_57 = _e180;
            let _e182 = l_8.T;
            param_58 = _e182;
            let _e183 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_57), (&param_58));
            frame_1 = _e183;
            let _e184 = frame_1;
            param_59 = _e184;
            let _e185 = (*wo_7);
            param_60 = _e185;
            let _e186 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_59), (&param_60));
            o_1 = _e186;
            let _e187 = frame_1;
            param_61 = _e187;
            let _e188 = (*wi_6);
            param_62 = _e188;
            let _e189 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_61), (&param_62));
            i_1 = _e189;
            fk = vec3<f32>(0f, 0f, 0f);
            pk = 0f;
            let _e190 = k;
            let _e193 = (*c_3).msPick[_e190];
            passes = select(1i, 2i, (_e193 > 0f));
            pass_ = 0i;
            loop {
                let _e196 = pass_;
                let _e197 = passes;
                if (_e196 < _e197) {
                    let _e199 = pass_;
                    shaped = (_e199 == 1i);
                    let _e201 = shaped;
                    if _e201 {
                        let _e203 = i_1[2u];
                        let _e205 = l_8;
                        param_63 = _e205;
                        param_64 = (_e203 < 0f);
                        let _e206 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_63), (&param_64));
                        local_8 = _e206;
                    } else {
                        let _e207 = l_8;
                        local_8 = _e207;
                    }
                    let _e208 = local_8;
                    m_4 = _e208;
                    let _e209 = shaped;
                    if _e209 {
                        let _e211 = i_1[2u];
                        if (_e211 > 0f) {
                            let _e213 = k;
                            let _e216 = (*c_3).msLobe[_e213];
                            local_10 = _e216;
                        } else {
                            let _e217 = k;
                            let _e220 = (*c_3).msLobeT[_e217];
                            local_10 = _e220;
                        }
                        let _e221 = local_10;
                        local_9 = _e221;
                    } else {
                        let _e223 = o_1[2u];
                        let _e225 = i_1[2u];
                        if ((_e223 * _e225) < 0f) {
                            let _e228 = k;
                            let _e231 = (*c_3).msT[_e228];
                            local_11 = vec3(_e231);
                        } else {
                            let _e233 = k;
                            let _e236 = (*c_3).ms[_e233];
                            local_11 = _e236;
                        }
                        let _e237 = local_11;
                        local_9 = _e237;
                    }
                    let _e238 = local_9;
                    scale = _e238;
                    let _e239 = scale;
                    let _e240 = m_4;
                    param_65 = _e240;
                    let _e241 = o_1;
                    param_66 = _e241;
                    let _e242 = i_1;
                    param_67 = _e242;
                    let _e243 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_65), (&param_66), (&param_67));
                    let _e245 = fk;
                    fk = (_e245 + (_e239 * _e243));
                    let _e247 = (*wantPdf);
                    if _e247 {
                        let _e248 = shaped;
                        if _e248 {
                            let _e249 = k;
                            let _e252 = (*c_3).msPick[_e249];
                            let _e254 = i_1[2u];
                            if (_e254 > 0f) {
                                let _e256 = k;
                                let _e259 = (*c_3).msSplit[_e256];
                                local_13 = _e259;
                            } else {
                                let _e260 = k;
                                let _e263 = (*c_3).msSplit[_e260];
                                local_13 = (1f - _e263);
                            }
                            let _e265 = local_13;
                            local_12 = (_e252 * _e265);
                        } else {
                            let _e267 = k;
                            let _e270 = (*c_3).msPick[_e267];
                            local_12 = (1f - _e270);
                        }
                        let _e272 = local_12;
                        share = _e272;
                        let _e273 = share;
                        let _e274 = m_4;
                        param_68 = _e274;
                        let _e275 = o_1;
                        param_69 = _e275;
                        let _e276 = i_1;
                        param_70 = _e276;
                        let _e277 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_68), (&param_69), (&param_70));
                        let _e279 = pk;
                        pk = (_e279 + (_e273 * _e277));
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e281 = pass_;
                    pass_ = (_e281 + 1i);
                }
            }
            let _e284 = l_8.weight;
            let _e286 = i_1[2u];
            let _e288 = l_8;
            param_71 = _e288;
            param_72 = abs(_e286);
            let _e289 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_71), (&param_72));
            let _e291 = fk;
            let _e293 = f_3;
            f_3 = (_e293 + ((_e284 * _e289) * _e291));
            let _e295 = (*wantPdf);
            if _e295 {
                let _e296 = k;
                let _e299 = (*c_3).choice[_e296];
                let _e300 = pk;
                let _e302 = p_1;
                p_1 = (_e302 + (_e299 * _e300));
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e304 = k;
            k = (_e304 + 1i);
        }
    }
    let _e307 = (*c_3).choiceTotal;
    if (_e307 > 0f) {
        let _e309 = p_1;
        let _e311 = (*c_3).choiceTotal;
        local_14 = (_e309 / _e311);
    } else {
        local_14 = 0f;
    }
    let _e313 = local_14;
    (*pdf) = _e313;
    let _e314 = f_3;
    return _e314;
}

fn mxc_env_to_world_u0028_vf3_u003b_f1_u003b(m_5: ptr<function, vec3<f32>>, angle: ptr<function, f32>) -> vec3<f32> {
    var c_4: f32;
    var s_4: f32;

    let _e128 = (*angle);
    c_4 = cos(_e128);
    let _e130 = (*angle);
    s_4 = sin(_e130);
    let _e132 = c_4;
    let _e134 = (*m_5)[0u];
    let _e136 = s_4;
    let _e138 = (*m_5)[2u];
    let _e142 = (*m_5)[1u];
    let _e143 = s_4;
    let _e146 = (*m_5)[0u];
    let _e148 = c_4;
    let _e150 = (*m_5)[2u];
    return vec3<f32>(((_e132 * _e134) + (_e136 * _e138)), _e142, ((-(_e143) * _e146) + (_e148 * _e150)));
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
    var param_73: f32;

    let _e139 = unnamed.mxc_env_size;
    size = max(_e139.xy, vec2<u32>(1u, 1u));
    let _e143 = size[0u];
    let _e145 = size[1u];
    n = (_e143 * _e145);
    let _e148 = (*u)[0u];
    let _e149 = n;
    let _e153 = n;
    k_1 = min(u32((_e148 * f32(_e149))), (_e153 - 1u));
    let _e156 = k_1;
    let _e159 = unnamed.mxc_env_cells[_e156];
    cell = _e159;
    let _e161 = (*u)[1u];
    let _e163 = cell[0u];
    if (_e161 >= _e163) {
        let _e166 = cell[1u];
        let _e168 = n;
        k_1 = min(bitcast<u32>(_e166), (_e168 - 1u));
    }
    let _e171 = k_1;
    let _e175 = unnamed.mxc_env_cells[_e171][2u];
    (*pdf_1) = _e175;
    let _e176 = k_1;
    let _e178 = size[0u];
    i_2 = (_e176 % _e178);
    let _e180 = k_1;
    let _e182 = size[0u];
    j = (_e180 / _e182);
    let _e184 = i_2;
    let _e187 = (*u)[2u];
    let _e190 = size[0u];
    phi = (6.2831855f * (((f32(_e184) + _e187) / f32(_e190)) - 0.5f));
    let _e195 = j;
    let _e199 = size[1u];
    y0_ = cos(((3.1415927f * f32(_e195)) / f32(_e199)));
    let _e203 = j;
    let _e208 = size[1u];
    y1_ = cos(((3.1415927f * f32((_e203 + 1u))) / f32(_e208)));
    let _e212 = y0_;
    let _e213 = y1_;
    let _e215 = (*u)[3u];
    y = mix(_e212, _e213, _e215);
    let _e217 = y;
    let _e218 = y;
    param_73 = (1f - (_e217 * _e218));
    let _e221 = mxc_safe_sqrt_u0028_f1_u003b((&param_73));
    r = _e221;
    let _e222 = r;
    let _e223 = phi;
    let _e226 = y;
    let _e227 = r;
    let _e229 = phi;
    return vec3<f32>((_e222 * sin(_e223)), _e226, (-(_e227) * cos(_e229)));
}

fn mxc_power_heuristic_u0028_f1_u003b_f1_u003b(a_4: ptr<function, f32>, b_1: ptr<function, f32>) -> f32 {
    var a2_1: f32;
    var b2_: f32;
    var local_15: f32;

    let _e129 = (*a_4);
    let _e130 = (*a_4);
    a2_1 = (_e129 * _e130);
    let _e132 = (*b_1);
    let _e133 = (*b_1);
    b2_ = (_e132 * _e133);
    let _e135 = a2_1;
    let _e136 = b2_;
    if ((_e135 + _e136) > 0f) {
        let _e139 = a2_1;
        let _e140 = a2_1;
        let _e141 = b2_;
        local_15 = (_e139 / (_e140 + _e141));
    } else {
        local_15 = 0f;
    }
    let _e144 = local_15;
    return _e144;
}

fn mxc_env_uv_u0028_vf3_u003b(d_1: ptr<function, vec3<f32>>) -> vec2<f32> {
    var u_1: f32;
    var local_16: f32;
    var v_3: f32;

    let _e129 = (*d_1)[0u];
    let _e132 = (*d_1)[2u];
    if ((abs(_e129) + abs(_e132)) > 0.000000000001f) {
        let _e137 = (*d_1)[0u];
        let _e139 = (*d_1)[2u];
        local_16 = (0.5f + (atan2(_e137, -(_e139)) * 0.15915494f));
    } else {
        local_16 = 0.5f;
    }
    let _e144 = local_16;
    u_1 = _e144;
    let _e145 = (*d_1);
    let _e149 = (*d_1)[1u];
    v_3 = (atan2(length(_e145.xz), _e149) * 0.31830987f);
    let _e152 = u_1;
    let _e153 = v_3;
    return vec2<f32>(_e152, _e153);
}

fn mxc_env_cell_u0028_vf3_u003b(d_2: ptr<function, vec3<f32>>) -> u32 {
    var uv: vec2<f32>;
    var param_74: vec3<f32>;
    var size_1: vec2<u32>;
    var i_3: u32;
    var j_1: u32;

    let _e130 = (*d_2);
    param_74 = _e130;
    let _e131 = mxc_env_uv_u0028_vf3_u003b((&param_74));
    uv = _e131;
    let _e133 = unnamed.mxc_env_size;
    size_1 = max(_e133.xy, vec2<u32>(1u, 1u));
    let _e137 = uv[0u];
    let _e140 = size_1[0u];
    let _e145 = size_1[0u];
    i_3 = min(u32((max(_e137, 0f) * f32(_e140))), (_e145 - 1u));
    let _e149 = uv[1u];
    let _e152 = size_1[1u];
    let _e157 = size_1[1u];
    j_1 = min(u32((max(_e149, 0f) * f32(_e152))), (_e157 - 1u));
    let _e160 = j_1;
    let _e162 = size_1[0u];
    let _e164 = i_3;
    return ((_e160 * _e162) + _e164);
}

fn mxc_env_pdf_u0028_vf3_u003b(d_3: ptr<function, vec3<f32>>) -> f32 {
    var param_75: vec3<f32>;

    let _e126 = (*d_3);
    param_75 = _e126;
    let _e127 = mxc_env_cell_u0028_vf3_u003b((&param_75));
    let _e131 = unnamed.mxc_env_cells[_e127][2u];
    return _e131;
}

fn mxc_env_to_map_u0028_vf3_u003b_f1_u003b(w: ptr<function, vec3<f32>>, angle_1: ptr<function, f32>) -> vec3<f32> {
    var c_5: f32;
    var s_5: f32;

    let _e128 = (*angle_1);
    c_5 = cos(_e128);
    let _e130 = (*angle_1);
    s_5 = sin(_e130);
    let _e132 = c_5;
    let _e134 = (*w)[0u];
    let _e136 = s_5;
    let _e138 = (*w)[2u];
    let _e142 = (*w)[1u];
    let _e143 = s_5;
    let _e145 = (*w)[0u];
    let _e147 = c_5;
    let _e149 = (*w)[2u];
    return vec3<f32>(((_e132 * _e134) - (_e136 * _e138)), _e142, ((_e143 * _e145) + (_e147 * _e149)));
}

fn mxc_env_lookup_u0028_vf3_u003b(d_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_76: vec3<f32>;

    let _e126 = (*d_4);
    param_76 = _e126;
    let _e127 = mxc_env_uv_u0028_vf3_u003b((&param_76));
    let _e128 = textureSampleLevel(mxc_env_radiance_texture, mxc_env_radiance_sampler, _e127, 0f);
    return _e128.xyz;
}

fn mxc_sky_u0028_vf3_u003b(d_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var y_1: f32;
    var horizon: vec3<f32>;
    var zenith: vec3<f32>;
    var ground: vec3<f32>;

    let _e130 = (*d_5)[1u];
    y_1 = clamp(_e130, -1f, 1f);
    horizon = vec3<f32>(1f, 0.96f, 0.9f);
    zenith = vec3<f32>(0.3f, 0.5f, 0.95f);
    ground = vec3<f32>(0.16f, 0.145f, 0.13f);
    let _e132 = y_1;
    if (_e132 >= 0f) {
        let _e134 = horizon;
        let _e135 = zenith;
        let _e136 = y_1;
        return mix(_e134, _e135, vec3(sqrt(_e136)));
    }
    let _e140 = horizon;
    let _e141 = ground;
    let _e142 = y_1;
    return mix(_e140, _e141, vec3(sqrt(-(_e142))));
}

fn mxc_environment_code_u0028_() -> i32 {
    var local_17: i32;

    if false {
        local_17 = MXC_ENVIRONMENT;
    } else {
        let _e127 = mxc_view.counts[1u];
        local_17 = _e127;
    }
    let _e128 = local_17;
    return _e128;
}

fn mxc_environment_u0028_vf3_u003b(d_6: ptr<function, vec3<f32>>) -> vec3<f32> {
    var code: i32;
    var param_77: vec3<f32>;
    var param_78: vec3<f32>;
    var param_79: f32;
    var param_80: vec3<f32>;

    let _e130 = mxc_environment_code_u0028_();
    code = _e130;
    let _e131 = code;
    if (_e131 == 1i) {
        let _e135 = mxc_view.environment[0u];
        return vec3(_e135);
    }
    let _e137 = code;
    if (_e137 == 2i) {
        let _e141 = mxc_view.environment[0u];
        let _e142 = (*d_6);
        param_77 = _e142;
        let _e143 = mxc_sky_u0028_vf3_u003b((&param_77));
        return (_e143 * _e141);
    }
    let _e145 = code;
    if (_e145 == 3i) {
        let _e149 = mxc_view.environment[0u];
        let _e150 = (*d_6);
        param_78 = _e150;
        let _e153 = mxc_view.environment[2u];
        param_79 = _e153;
        let _e154 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_78), (&param_79));
        param_80 = _e154;
        let _e155 = mxc_env_lookup_u0028_vf3_u003b((&param_80));
        return (_e155 * _e149);
    }
    return vec3<f32>(0f, 0f, 0f);
}

fn mxc_exit_direction_u0028_vf3_u003b_vf3_u003b(d_7: ptr<function, vec3<f32>>, t_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var axis: vec3<f32>;
    var s_6: f32;
    var c_6: f32;

    let _e129 = (*d_7);
    let _e130 = (*t_2);
    axis = cross(_e129, _e130);
    let _e132 = axis;
    s_6 = length(_e132);
    let _e134 = s_6;
    if (_e134 < 0.000001f) {
        let _e136 = (*t_2);
        return _e136;
    }
    let _e137 = s_6;
    let _e138 = axis;
    axis = (_e138 / vec3(_e137));
    let _e141 = (*d_7);
    let _e142 = (*t_2);
    c_6 = dot(_e141, _e142);
    let _e144 = (*t_2);
    let _e145 = c_6;
    let _e147 = axis;
    let _e148 = (*t_2);
    let _e150 = s_6;
    let _e153 = axis;
    let _e154 = axis;
    let _e155 = (*t_2);
    let _e158 = c_6;
    return (((_e144 * _e145) + (cross(_e147, _e148) * _e150)) + ((_e153 * dot(_e154, _e155)) * (1f - _e158)));
}

fn mxc_to_world_u0028_mf33_u003b_vf3_u003b(frame_2: ptr<function, mat3x3<f32>>, v_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e127 = (*frame_2)[0];
    let _e129 = (*v_4)[0u];
    let _e132 = (*frame_2)[1];
    let _e134 = (*v_4)[1u];
    let _e138 = (*frame_2)[2];
    let _e140 = (*v_4)[2u];
    return (((_e127 * _e129) + (_e132 * _e134)) + (_e138 * _e140));
}

fn mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b(wo_8: ptr<function, vec3<f32>>, alpha_7: ptr<function, vec2<f32>>, u_2: ptr<function, vec2<f32>>) -> vec3<f32> {
    var param_81: vec2<f32>;
    var vh: vec3<f32>;
    var lensq: f32;
    var t1_: vec3<f32>;
    var local_18: vec3<f32>;
    var t2_: vec3<f32>;
    var r_1: f32;
    var phi_1: f32;
    var p1_: f32;
    var p2_: f32;
    var s_7: f32;
    var param_82: f32;
    var nh: vec3<f32>;
    var param_83: f32;

    let _e141 = (*alpha_7);
    param_81 = _e141;
    let _e142 = mxc_rough_alpha_u0028_vf2_u003b((&param_81));
    (*alpha_7) = _e142;
    let _e144 = (*alpha_7)[0u];
    let _e146 = (*wo_8)[0u];
    let _e149 = (*alpha_7)[1u];
    let _e151 = (*wo_8)[1u];
    let _e154 = (*wo_8)[2u];
    vh = normalize(vec3<f32>((_e144 * _e146), (_e149 * _e151), _e154));
    let _e158 = vh[0u];
    let _e160 = vh[0u];
    let _e163 = vh[1u];
    let _e165 = vh[1u];
    lensq = ((_e158 * _e160) + (_e163 * _e165));
    let _e168 = lensq;
    if (_e168 > 0f) {
        let _e171 = vh[1u];
        let _e174 = vh[0u];
        let _e176 = lensq;
        local_18 = (vec3<f32>(-(_e171), _e174, 0f) * inverseSqrt(_e176));
    } else {
        local_18 = vec3<f32>(1f, 0f, 0f);
    }
    let _e179 = local_18;
    t1_ = _e179;
    let _e180 = vh;
    let _e181 = t1_;
    t2_ = cross(_e180, _e181);
    let _e184 = (*u_2)[0u];
    r_1 = sqrt(_e184);
    let _e187 = (*u_2)[1u];
    phi_1 = (6.2831855f * _e187);
    let _e189 = r_1;
    let _e190 = phi_1;
    p1_ = (_e189 * cos(_e190));
    let _e193 = r_1;
    let _e194 = phi_1;
    p2_ = (_e193 * sin(_e194));
    let _e198 = vh[2u];
    s_7 = (0.5f * (1f + _e198));
    let _e201 = s_7;
    let _e203 = p1_;
    let _e204 = p1_;
    param_82 = (1f - (_e203 * _e204));
    let _e207 = mxc_safe_sqrt_u0028_f1_u003b((&param_82));
    let _e209 = s_7;
    let _e210 = p2_;
    p2_ = (((1f - _e201) * _e207) + (_e209 * _e210));
    let _e213 = p1_;
    let _e214 = t1_;
    let _e216 = p2_;
    let _e217 = t2_;
    let _e220 = p1_;
    let _e221 = p1_;
    let _e224 = p2_;
    let _e225 = p2_;
    param_83 = ((1f - (_e220 * _e221)) - (_e224 * _e225));
    let _e228 = mxc_safe_sqrt_u0028_f1_u003b((&param_83));
    let _e229 = vh;
    nh = (((_e214 * _e213) + (_e217 * _e216)) + (_e229 * _e228));
    let _e233 = (*alpha_7)[0u];
    let _e235 = nh[0u];
    let _e238 = (*alpha_7)[1u];
    let _e240 = nh[1u];
    let _e243 = nh[2u];
    return normalize(vec3<f32>((_e233 * _e235), (_e238 * _e240), max(_e243, 0f)));
}

fn mxc_sample_cosine_u0028_vf2_u003b(u_3: ptr<function, vec2<f32>>) -> vec3<f32> {
    var r_2: f32;
    var phi_2: f32;
    var param_84: f32;

    let _e129 = (*u_3)[0u];
    r_2 = sqrt(_e129);
    let _e132 = (*u_3)[1u];
    phi_2 = (6.2831855f * _e132);
    let _e134 = r_2;
    let _e135 = phi_2;
    let _e138 = r_2;
    let _e139 = phi_2;
    let _e143 = (*u_3)[0u];
    param_84 = (1f - _e143);
    let _e145 = mxc_safe_sqrt_u0028_f1_u003b((&param_84));
    return vec3<f32>((_e134 * cos(_e135)), (_e138 * sin(_e139)), _e145);
}

fn mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_9: ptr<function, MxcLobe>, wo_9: ptr<function, vec3<f32>>, u_4: ptr<function, vec3<f32>>) -> MxcLobeSample {
    var s_8: MxcLobeSample;
    var above_3: bool;
    var o_2: vec3<f32>;
    var local_19: vec3<f32>;
    var delta: bool;
    var param_85: vec2<f32>;
    var m_6: vec3<f32>;
    var local_20: vec3<f32>;
    var param_86: vec3<f32>;
    var param_87: vec2<f32>;
    var param_88: vec2<f32>;
    var hm: f32;
    var transmits: bool;
    var param_89: MxcLobe;
    var reflects: bool;
    var f_4: vec3<f32>;
    var param_90: MxcLobe;
    var param_91: f32;
    var param_92: bool;
    var fr_1: f32;
    var local_21: f32;
    var param_93: vec3<f32>;
    var pReflect: f32;
    var local_22: f32;
    var i_4: vec3<f32>;
    var local_23: vec3<f32>;
    var tint: vec3<f32>;
    var local_24: vec3<f32>;
    var local_25: vec3<f32>;
    var param_94: MxcLobe;
    var param_95: vec3<f32>;
    var param_96: vec3<f32>;
    var param_97: MxcLobe;
    var param_98: vec3<f32>;
    var param_99: vec3<f32>;
    var param_100: vec2<f32>;
    var param_101: MxcLobe;
    var param_102: vec3<f32>;
    var param_103: vec3<f32>;
    var param_104: MxcLobe;
    var param_105: vec3<f32>;
    var param_106: vec3<f32>;
    var phi_2887_: bool;
    var phi_2892_: bool;
    var phi_2903_: bool;

    s_8.valid = false;
    s_8.delta = false;
    s_8.pdf = 0f;
    s_8.value = vec3<f32>(0f, 0f, 0f);
    s_8.wi = vec3<f32>(0f, 0f, 1f);
    let _e175 = (*l_9).kind;
    switch _e175 {
        case 2, 3, 1: {
            let _e202 = (*wo_9)[2u];
            above_3 = (_e202 > 0f);
            let _e204 = above_3;
            if _e204 {
                let _e205 = (*wo_9);
                local_19 = _e205;
            } else {
                let _e206 = (*wo_9);
                local_19 = -(_e206);
            }
            let _e208 = local_19;
            o_2 = _e208;
            let _e210 = o_2[2u];
            if (_e210 <= 0f) {
                let _e212 = s_8;
                return _e212;
            }
            let _e214 = (*l_9).alpha;
            param_85 = _e214;
            let _e215 = mxc_is_delta_u0028_vf2_u003b((&param_85));
            delta = _e215;
            let _e216 = delta;
            if _e216 {
                local_20 = vec3<f32>(0f, 0f, 1f);
            } else {
                let _e217 = o_2;
                param_86 = _e217;
                let _e219 = (*l_9).alpha;
                param_87 = _e219;
                let _e220 = (*u_4);
                param_88 = _e220.xy;
                let _e222 = mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b((&param_86), (&param_87), (&param_88));
                local_20 = _e222;
            }
            let _e223 = local_20;
            m_6 = _e223;
            let _e224 = o_2;
            let _e225 = m_6;
            hm = dot(_e224, _e225);
            let _e228 = (*l_9).kind;
            let _e229 = (_e228 == 1i);
            phi_2887_ = _e229;
            if !(_e229) {
                let _e232 = (*l_9).kind;
                phi_2887_ = (_e232 == 3i);
            }
            let _e235 = phi_2887_;
            phi_2892_ = _e235;
            if _e235 {
                let _e236 = (*l_9);
                param_89 = _e236;
                let _e237 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_89));
                phi_2892_ = _e237;
            }
            let _e239 = phi_2892_;
            transmits = _e239;
            let _e241 = (*l_9).kind;
            let _e242 = (_e241 == 2i);
            phi_2903_ = _e242;
            if !(_e242) {
                let _e245 = (*l_9).mode;
                phi_2903_ = ((_e245 & 1i) != 0i);
            }
            let _e249 = phi_2903_;
            reflects = _e249;
            let _e250 = hm;
            let _e252 = (*l_9);
            param_90 = _e252;
            param_91 = max(_e250, 0f);
            let _e253 = above_3;
            param_92 = _e253;
            let _e254 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_90), (&param_91), (&param_92));
            f_4 = _e254;
            let _e255 = transmits;
            if _e255 {
                let _e256 = f_4;
                param_93 = _e256;
                let _e257 = mxc_mean_u0028_vf3_u003b((&param_93));
                local_21 = _e257;
            } else {
                local_21 = 1f;
            }
            let _e258 = local_21;
            fr_1 = _e258;
            let _e259 = transmits;
            if _e259 {
                let _e260 = reflects;
                let _e261 = fr_1;
                local_22 = select(0f, _e261, _e260);
            } else {
                local_22 = 1f;
            }
            let _e263 = local_22;
            pReflect = _e263;
            let _e265 = (*u_4)[2u];
            let _e266 = pReflect;
            if (_e265 < _e266) {
                let _e268 = o_2;
                let _e270 = m_6;
                i_4 = reflect(-(_e268), _e270);
                let _e273 = i_4[2u];
                if (_e273 <= 0f) {
                    let _e275 = s_8;
                    return _e275;
                }
                let _e276 = above_3;
                if _e276 {
                    let _e277 = i_4;
                    local_23 = _e277;
                } else {
                    let _e278 = i_4;
                    local_23 = -(_e278);
                }
                let _e280 = local_23;
                s_8.wi = _e280;
                let _e282 = delta;
                s_8.delta = _e282;
                let _e284 = delta;
                if _e284 {
                    let _e286 = (*l_9).kind;
                    if (_e286 == 1i) {
                        let _e288 = above_3;
                        if _e288 {
                            let _e290 = (*l_9).c0_;
                            local_25 = _e290;
                        } else {
                            local_25 = vec3<f32>(1f, 1f, 1f);
                        }
                        let _e291 = local_25;
                        local_24 = _e291;
                    } else {
                        local_24 = vec3<f32>(1f, 1f, 1f);
                    }
                    let _e292 = local_24;
                    tint = _e292;
                    let _e293 = f_4;
                    let _e294 = tint;
                    s_8.value = (_e293 * _e294);
                    let _e297 = pReflect;
                    s_8.pdf = _e297;
                } else {
                    let _e299 = (*l_9);
                    param_94 = _e299;
                    let _e300 = (*wo_9);
                    param_95 = _e300;
                    let _e302 = s_8.wi;
                    param_96 = _e302;
                    let _e303 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_94), (&param_95), (&param_96));
                    s_8.value = _e303;
                    let _e305 = (*l_9);
                    param_97 = _e305;
                    let _e306 = (*wo_9);
                    param_98 = _e306;
                    let _e308 = s_8.wi;
                    param_99 = _e308;
                    let _e309 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_97), (&param_98), (&param_99));
                    s_8.pdf = _e309;
                }
                let _e312 = s_8.pdf;
                s_8.valid = (_e312 > 0f);
                let _e315 = s_8;
                return _e315;
            }
            let _e316 = s_8;
            return _e316;
        }
        default: {
            let _e177 = (*wo_9)[2u];
            if (_e177 <= 0f) {
                let _e179 = s_8;
                return _e179;
            }
            let _e180 = (*u_4);
            param_100 = _e180.xy;
            let _e182 = mxc_sample_cosine_u0028_vf2_u003b((&param_100));
            s_8.wi = _e182;
            let _e184 = (*l_9);
            param_101 = _e184;
            let _e185 = (*wo_9);
            param_102 = _e185;
            let _e187 = s_8.wi;
            param_103 = _e187;
            let _e188 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_101), (&param_102), (&param_103));
            s_8.value = _e188;
            let _e190 = (*l_9);
            param_104 = _e190;
            let _e191 = (*wo_9);
            param_105 = _e191;
            let _e193 = s_8.wi;
            param_106 = _e193;
            let _e194 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_104), (&param_105), (&param_106));
            s_8.pdf = _e194;
            let _e197 = s_8.pdf;
            s_8.valid = (_e197 > 0f);
            let _e200 = s_8;
            return _e200;
        }
    }
}

fn mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b(c_7: ptr<function, MxcClosure>, wo_10: ptr<function, vec3<f32>>, u_5: ptr<function, vec3<f32>>) -> MxcSample {
    var s_9: MxcSample;
    var total: f32;
    var x_2: f32;
    var chosen: i32;
    var before: f32;
    var p_2: f32;
    var lastBefore: f32;
    var last: i32;
    var k_2: i32;
    var pk_1: f32;
    var uz: f32;
    var l_10: MxcLobe;
    var frame_3: mat3x3<f32>;
    var param_107: vec3<f32>;
    var param_108: vec3<f32>;
    var o_3: vec3<f32>;
    var param_109: mat3x3<f32>;
    var param_110: vec3<f32>;
    var q: f32;
    var shaped_1: bool;
    var reflected: bool;
    var v_5: f32;
    var split: f32;
    var local_26: f32;
    var m_7: MxcLobe;
    var local_27: MxcLobe;
    var param_111: MxcLobe;
    var param_112: bool;
    var ls: MxcLobeSample;
    var param_113: MxcLobe;
    var param_114: vec3<f32>;
    var param_115: vec3<f32>;
    var param_116: mat3x3<f32>;
    var param_117: vec3<f32>;
    var param_118: MxcLobe;
    var param_119: f32;

    s_9.valid = false;
    s_9.delta = false;
    s_9.evaluate = false;
    s_9.pdf = 0f;
    s_9.weight = vec3<f32>(0f, 0f, 0f);
    let _e168 = (*wo_10);
    s_9.wi = _e168;
    let _e171 = (*c_7).choiceTotal;
    total = _e171;
    let _e173 = (*c_7).count;
    let _e175 = total;
    if ((_e173 == 0i) || (_e175 <= 0f)) {
        let _e178 = s_9;
        return _e178;
    }
    let _e180 = (*u_5)[2u];
    let _e181 = total;
    x_2 = (_e180 * _e181);
    chosen = -1i;
    before = 0f;
    p_2 = 0f;
    lastBefore = 0f;
    last = -1i;
    k_2 = 0i;
    loop {
        let _e183 = k_2;
        let _e185 = (*c_7).count;
        if (_e183 < _e185) {
            let _e187 = k_2;
            let _e190 = (*c_7).choice[_e187];
            pk_1 = _e190;
            let _e191 = pk_1;
            if (_e191 <= 0f) {
                continue;
            }
            let _e193 = x_2;
            let _e194 = before;
            let _e195 = pk_1;
            if (_e193 < (_e194 + _e195)) {
                let _e198 = k_2;
                chosen = _e198;
                let _e199 = pk_1;
                p_2 = _e199;
                break;
            }
            let _e200 = k_2;
            last = _e200;
            let _e201 = before;
            lastBefore = _e201;
            let _e202 = pk_1;
            let _e203 = before;
            before = (_e203 + _e202);
            continue;
        } else {
            break;
        }
        continuing {
            let _e205 = k_2;
            k_2 = (_e205 + 1i);
        }
    }
    let _e207 = chosen;
    if (_e207 < 0i) {
        let _e209 = last;
        chosen = max(_e209, 0i);
        let _e211 = chosen;
        let _e214 = (*c_7).choice[_e211];
        p_2 = _e214;
        let _e215 = lastBefore;
        before = _e215;
    }
    let _e216 = p_2;
    if (_e216 <= 0f) {
        let _e218 = s_9;
        return _e218;
    }
    let _e219 = x_2;
    let _e220 = before;
    let _e222 = p_2;
    uz = clamp(((_e219 - _e220) / _e222), 0f, 0.99999994f);
    let _e225 = chosen;
    let _e228 = (*c_7).lobes[_e225];
    l_10 = _e228;
    let _e230 = l_10.N;
    param_107 = _e230;
    let _e232 = l_10.T;
    param_108 = _e232;
    let _e233 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_107), (&param_108));
    frame_3 = _e233;
    let _e234 = frame_3;
    param_109 = _e234;
    let _e235 = (*wo_10);
    param_110 = _e235;
    let _e236 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_109), (&param_110));
    o_3 = _e236;
    let _e237 = chosen;
    let _e240 = (*c_7).msPick[_e237];
    q = _e240;
    let _e241 = uz;
    let _e242 = q;
    shaped_1 = (_e241 < _e242);
    reflected = true;
    let _e244 = shaped_1;
    if _e244 {
        let _e245 = uz;
        let _e246 = q;
        v_5 = (_e245 / _e246);
        let _e248 = chosen;
        let _e251 = (*c_7).msSplit[_e248];
        split = _e251;
        let _e252 = v_5;
        let _e253 = split;
        reflected = (_e252 < _e253);
        let _e255 = reflected;
        if _e255 {
            let _e256 = v_5;
            let _e257 = split;
            local_26 = (_e256 / max(_e257, 0.000001f));
        } else {
            let _e260 = v_5;
            let _e261 = split;
            let _e263 = split;
            local_26 = ((_e260 - _e261) / max((1f - _e263), 0.000001f));
        }
        let _e267 = local_26;
        uz = _e267;
    } else {
        let _e268 = uz;
        let _e269 = q;
        let _e271 = q;
        uz = ((_e268 - _e269) / (1f - _e271));
    }
    let _e274 = shaped_1;
    if _e274 {
        let _e275 = reflected;
        let _e277 = l_10;
        param_111 = _e277;
        param_112 = !(_e275);
        let _e278 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_111), (&param_112));
        local_27 = _e278;
    } else {
        let _e279 = l_10;
        local_27 = _e279;
    }
    let _e280 = local_27;
    m_7 = _e280;
    let _e281 = (*u_5);
    let _e282 = _e281.xy;
    let _e283 = uz;
    let _e288 = m_7;
    param_113 = _e288;
    let _e289 = o_3;
    param_114 = _e289;
    param_115 = vec3<f32>(_e282.x, _e282.y, min(_e283, 0.99999994f));
    let _e290 = mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_113), (&param_114), (&param_115));
    ls = _e290;
    let _e292 = ls.valid;
    if !(_e292) {
        let _e294 = s_9;
        return _e294;
    }
    let _e295 = frame_3;
    param_116 = _e295;
    let _e297 = ls.wi;
    param_117 = _e297;
    let _e298 = mxc_to_world_u0028_mf33_u003b_vf3_u003b((&param_116), (&param_117));
    s_9.wi = _e298;
    let _e301 = ls.delta;
    if _e301 {
        s_9.delta = true;
        let _e304 = ls.pdf;
        let _e305 = p_2;
        let _e307 = total;
        s_9.pdf = ((_e304 * _e305) / _e307);
        let _e311 = l_10.weight;
        let _e312 = chosen;
        let _e315 = (*c_7).ms[_e312];
        let _e319 = ls.wi[2u];
        let _e321 = l_10;
        param_118 = _e321;
        param_119 = abs(_e319);
        let _e322 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_118), (&param_119));
        let _e325 = ls.value;
        let _e328 = s_9.pdf;
        s_9.weight = ((((_e311 * _e315) * _e322) * _e325) / vec3(_e328));
        let _e333 = s_9.pdf;
        s_9.valid = (_e333 > 0f);
        let _e336 = s_9;
        return _e336;
    }
    s_9.evaluate = true;
    s_9.valid = true;
    let _e339 = s_9;
    return _e339;
}

fn mxc_radical_inverse_u0028_u1_u003b_u1_u003b(i_5: ptr<function, u32>, base: ptr<function, u32>) -> f32 {
    var inv: f32;
    var f_5: f32;
    var r_3: f32;

    let _e129 = (*base);
    if (_e129 == 2u) {
        let _e131 = (*i_5);
        return (f32((reverseBits(_e131) >> bitcast<u32>(8i))) * 0.000000059604645f);
    }
    let _e137 = (*base);
    inv = (1f / f32(_e137));
    let _e140 = inv;
    f_5 = _e140;
    r_3 = 0f;
    loop {
        let _e141 = (*i_5);
        if (_e141 > 0u) {
            let _e143 = f_5;
            let _e144 = (*i_5);
            let _e145 = (*base);
            let _e149 = r_3;
            r_3 = (_e149 + (_e143 * f32((_e144 % _e145))));
            let _e151 = inv;
            let _e152 = f_5;
            f_5 = (_e152 * _e151);
            continue;
        } else {
            break;
        }
        continuing {
            let _e154 = (*base);
            let _e155 = (*i_5);
            (*i_5) = (_e155 / _e154);
        }
    }
    let _e157 = r_3;
    return min(_e157, 0.99999994f);
}

fn mxc_pcg_u0028_u1_u003b(v_6: ptr<function, u32>) -> u32 {
    var state: u32;
    var word: u32;

    let _e127 = (*v_6);
    state = ((_e127 * 747796405u) + 2891336453u);
    let _e130 = state;
    let _e131 = state;
    let _e137 = state;
    word = (((_e130 >> bitcast<u32>(((_e131 >> bitcast<u32>(28u)) + 4u))) ^ _e137) * 277803737u);
    let _e140 = word;
    let _e143 = word;
    return ((_e140 >> bitcast<u32>(22u)) ^ _e143);
}

fn mxc_uniform_u0028_u1_u003b(seed: ptr<function, u32>) -> f32 {
    var param_120: u32;

    let _e126 = (*seed);
    param_120 = _e126;
    let _e127 = mxc_pcg_u0028_u1_u003b((&param_120));
    (*seed) = _e127;
    let _e128 = (*seed);
    return (f32((_e128 >> bitcast<u32>(8i))) * 0.000000059604645f);
}

fn mxc_light_kinds_u0028_() -> i32 {
    return 7i;
}

fn mxc_light_count_u0028_() -> i32 {
    var local_28: i32;

    if false {
        local_28 = MXC_LIGHT_COUNT;
    } else {
        let _e127 = mxc_view.counts[0u];
        local_28 = _e127;
    }
    let _e128 = local_28;
    return min(_e128, 8i);
}

fn mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b(mu_2: ptr<function, f32>, x_3: ptr<function, f32>, firstRow: ptr<function, f32>) -> vec4<f32> {
    var t_3: vec2<f32>;

    let _e128 = (*mu_2);
    let _e131 = (*x_3);
    t_3 = ((vec2<f32>(sqrt(clamp(_e128, 0f, 1f)), clamp(_e131, 0f, 1f)) * 31f) + vec2(0.5f));
    let _e138 = t_3[0u];
    let _e140 = (*firstRow);
    let _e142 = t_3[1u];
    let _e146 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, vec2<f32>((_e138 / 32f), ((_e140 + _e142) / 2070f)), 0f);
    return _e146;
}

fn mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b(mu_3: ptr<function, f32>, alpha_8: ptr<function, f32>, e: ptr<function, f32>) -> vec4<f32> {
    var s_10: f32;
    var s0_: f32;
    var x_4: f32;
    var a_5: vec4<f32>;
    var param_121: f32;
    var param_122: f32;
    var param_123: f32;
    var b_2: vec4<f32>;
    var param_124: f32;
    var param_125: f32;
    var param_126: f32;

    let _e138 = (*e);
    s_10 = (sqrt(clamp((0.5f * (_e138 - 1f)), 0f, 1f)) * 31f);
    let _e144 = s_10;
    s0_ = min(floor(_e144), 30f);
    let _e147 = (*alpha_8);
    x_4 = sqrt(max(_e147, 0f));
    let _e150 = s0_;
    let _e153 = (*mu_3);
    param_121 = _e153;
    let _e154 = x_4;
    param_122 = _e154;
    param_123 = (32f * (1f + _e150));
    let _e155 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_121), (&param_122), (&param_123));
    a_5 = _e155;
    let _e156 = s0_;
    let _e159 = (*mu_3);
    param_124 = _e159;
    let _e160 = x_4;
    param_125 = _e160;
    param_126 = (32f * (2f + _e156));
    let _e161 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_124), (&param_125), (&param_126));
    b_2 = _e161;
    let _e162 = a_5;
    let _e163 = b_2;
    let _e164 = s_10;
    let _e165 = s0_;
    return mix(_e162, _e163, vec4((_e164 - _e165)));
}

fn mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b(mu_4: ptr<function, f32>, alpha_9: ptr<function, f32>, eta_1: ptr<function, f32>) -> f32 {
    var param_127: f32;
    var param_128: f32;
    var param_129: f32;
    var param_130: f32;
    var param_131: f32;
    var param_132: f32;

    let _e133 = (*eta_1);
    if (_e133 >= 1f) {
        let _e135 = (*mu_4);
        param_127 = _e135;
        let _e136 = (*alpha_9);
        param_128 = _e136;
        let _e137 = (*eta_1);
        param_129 = _e137;
        let _e138 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_127), (&param_128), (&param_129));
        return _e138.y;
    }
    let _e140 = (*eta_1);
    let _e143 = (*mu_4);
    param_130 = _e143;
    let _e144 = (*alpha_9);
    param_131 = _e144;
    param_132 = (1f / max(_e140, 0.001f));
    let _e145 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_130), (&param_131), (&param_132));
    return _e145.z;
}

fn mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b(mu_5: ptr<function, f32>, alpha_10: ptr<function, f32>, eta_2: ptr<function, f32>) -> f32 {
    var e_1: f32;
    var local_29: f32;
    var param_133: f32;
    var param_134: f32;
    var param_135: f32;

    let _e132 = (*eta_2);
    if (_e132 >= 1f) {
        let _e134 = (*eta_2);
        local_29 = _e134;
    } else {
        let _e135 = (*eta_2);
        local_29 = (1f / max(_e135, 0.001f));
    }
    let _e138 = local_29;
    e_1 = _e138;
    let _e139 = (*mu_5);
    param_133 = _e139;
    let _e140 = (*alpha_10);
    param_134 = _e140;
    let _e141 = e_1;
    param_135 = _e141;
    let _e142 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_133), (&param_134), (&param_135));
    return _e142.x;
}

fn mxc_table_u0028_f1_u003b_f1_u003b(mu_6: ptr<function, f32>, x_5: ptr<function, f32>) -> vec4<f32> {
    var param_136: f32;
    var param_137: f32;
    var param_138: f32;

    let _e129 = (*mu_6);
    param_136 = _e129;
    let _e130 = (*x_5);
    param_137 = _e130;
    param_138 = 0f;
    let _e131 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_136), (&param_137), (&param_138));
    return _e131;
}

fn mxc_split_sum_u0028_f1_u003b_f1_u003b(mu_7: ptr<function, f32>, alpha_11: ptr<function, f32>) -> vec2<f32> {
    var param_139: f32;
    var param_140: f32;

    let _e128 = (*alpha_11);
    let _e131 = (*mu_7);
    param_139 = _e131;
    param_140 = sqrt(max(_e128, 0f));
    let _e132 = mxc_table_u0028_f1_u003b_f1_u003b((&param_139), (&param_140));
    return _e132.xy;
}

fn mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_11: ptr<function, MxcLobe>, wo_11: ptr<function, vec3<f32>>, ms: ptr<function, vec3<f32>>) -> vec3<f32> {
    var mu_8: f32;
    var alpha_12: f32;
    var param_141: vec2<f32>;
    var e_2: vec3<f32>;
    var param_142: f32;
    var param_143: f32;
    var param_144: f32;
    var ab: vec2<f32>;
    var param_145: f32;
    var param_146: f32;
    var f0_: vec3<f32>;
    var param_147: MxcLobe;
    var param_148: f32;
    var param_149: bool;
    var f90_: vec3<f32>;
    var param_150: MxcLobe;
    var param_151: f32;
    var param_152: bool;
    var tint_1: vec3<f32>;
    var local_30: vec3<f32>;
    var param_153: vec2<f32>;
    var param_154: MxcLobe;
    var param_155: f32;
    var param_156: bool;
    var phi_2400_: bool;
    var phi_2407_: bool;
    var phi_2425_: bool;

    let _e152 = (*wo_11)[2u];
    mu_8 = clamp(_e152, 0f, 1f);
    let _e155 = (*l_11).kind;
    let _e156 = (_e155 == 1i);
    phi_2400_ = _e156;
    if !(_e156) {
        let _e159 = (*l_11).kind;
        phi_2400_ = (_e159 == 2i);
    }
    let _e162 = phi_2400_;
    phi_2407_ = _e162;
    if !(_e162) {
        let _e165 = (*l_11).kind;
        phi_2407_ = (_e165 == 3i);
    }
    let _e168 = phi_2407_;
    if _e168 {
        let _e171 = (*l_11).alpha[0u];
        let _e174 = (*l_11).alpha[1u];
        alpha_12 = sqrt((_e171 * _e174));
        let _e178 = (*l_11).kind;
        let _e179 = (_e178 == 1i);
        phi_2425_ = _e179;
        if _e179 {
            let _e181 = (*l_11).alpha;
            param_141 = _e181;
            let _e182 = mxc_is_delta_u0028_vf2_u003b((&param_141));
            phi_2425_ = !(_e182);
        }
        let _e185 = phi_2425_;
        if _e185 {
            let _e186 = mu_8;
            param_142 = _e186;
            let _e187 = alpha_12;
            param_143 = _e187;
            let _e189 = (*l_11).eta;
            param_144 = _e189;
            let _e190 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_142), (&param_143), (&param_144));
            e_2 = vec3(_e190);
            let _e192 = e_2;
            let _e194 = (*l_11).c0_;
            let _e196 = (*ms);
            return clamp(((_e192 * _e194) * _e196), vec3(0f), vec3(1f));
        }
        let _e201 = mu_8;
        param_145 = _e201;
        let _e202 = alpha_12;
        param_146 = _e202;
        let _e203 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_145), (&param_146));
        ab = _e203;
        let _e204 = (*l_11);
        param_147 = _e204;
        param_148 = 1f;
        param_149 = true;
        let _e205 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_147), (&param_148), (&param_149));
        f0_ = _e205;
        let _e206 = (*l_11);
        param_150 = _e206;
        param_151 = 0f;
        param_152 = true;
        let _e207 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_150), (&param_151), (&param_152));
        f90_ = _e207;
        let _e209 = (*l_11).kind;
        if (_e209 == 1i) {
            let _e212 = (*l_11).c0_;
            local_30 = _e212;
        } else {
            local_30 = vec3<f32>(1f, 1f, 1f);
        }
        let _e213 = local_30;
        tint_1 = _e213;
        let _e215 = (*l_11).alpha;
        param_153 = _e215;
        let _e216 = mxc_is_delta_u0028_vf2_u003b((&param_153));
        if _e216 {
            let _e217 = (*l_11);
            param_154 = _e217;
            let _e218 = mu_8;
            param_155 = _e218;
            param_156 = true;
            let _e219 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_154), (&param_155), (&param_156));
            let _e220 = tint_1;
            return (_e219 * _e220);
        }
        let _e222 = f0_;
        let _e224 = ab[0u];
        let _e226 = f90_;
        let _e228 = ab[1u];
        let _e231 = tint_1;
        let _e233 = (*ms);
        return clamp(((((_e222 * _e224) + (_e226 * _e228)) * _e231) * _e233), vec3(0f), vec3(1f));
    }
    let _e239 = (*l_11).kind;
    if (_e239 == 8i) {
        let _e242 = (*l_11).c0_;
        return _e242;
    }
    let _e244 = (*l_11).c0_;
    return _e244;
}

fn mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_12: ptr<function, MxcLobe>, wo_12: ptr<function, vec3<f32>>) -> bool {
    var phi_2026_: bool;

    let _e127 = (*wo_12)[2u];
    let _e128 = (_e127 <= 0f);
    phi_2026_ = _e128;
    if !(_e128) {
        let _e131 = (*l_12).eta;
        phi_2026_ = (_e131 < 1f);
    }
    let _e134 = phi_2026_;
    if _e134 {
        return false;
    }
    return true;
}

fn mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_13: ptr<function, MxcLobe>) -> bool {
    let _e126 = (*l_13).eta;
    return (abs((_e126 - 1f)) < 0.0001f);
}

fn mxc_lobe_ms_shaped_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_14: ptr<function, MxcLobe>, wo_13: ptr<function, vec3<f32>>) -> bool {
    var param_157: vec2<f32>;
    var param_158: MxcLobe;
    var param_159: MxcLobe;
    var param_160: vec3<f32>;
    var phi_2279_: bool;
    var phi_2305_: bool;
    var phi_2312_: bool;
    var phi_2318_: bool;
    var phi_2324_: bool;

    let _e131 = (*wo_13)[2u];
    let _e132 = (_e131 <= 0f);
    phi_2279_ = _e132;
    if !(_e132) {
        let _e135 = (*l_14).alpha;
        param_157 = _e135;
        let _e136 = mxc_is_delta_u0028_vf2_u003b((&param_157));
        phi_2279_ = _e136;
    }
    let _e138 = phi_2279_;
    if _e138 {
        return false;
    }
    let _e140 = (*l_14).kind;
    if (_e140 == 2i) {
        return true;
    }
    let _e143 = (*l_14).kind;
    if (_e143 == 3i) {
        let _e146 = (*l_14).mode;
        return ((_e146 & 1i) != 0i);
    }
    let _e150 = (*l_14).kind;
    let _e151 = (_e150 == 1i);
    phi_2305_ = _e151;
    if _e151 {
        let _e153 = (*l_14).mode;
        phi_2305_ = ((_e153 & 1i) != 0i);
    }
    let _e157 = phi_2305_;
    phi_2312_ = _e157;
    if _e157 {
        let _e159 = (*l_14).mode;
        phi_2312_ = ((_e159 & 4i) == 0i);
    }
    let _e163 = phi_2312_;
    phi_2318_ = _e163;
    if _e163 {
        let _e164 = (*l_14);
        param_158 = _e164;
        let _e165 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_158));
        phi_2318_ = !(_e165);
    }
    let _e168 = phi_2318_;
    phi_2324_ = _e168;
    if _e168 {
        let _e169 = (*l_14);
        param_159 = _e169;
        let _e170 = (*wo_13);
        param_160 = _e170;
        let _e171 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_159), (&param_160));
        phi_2324_ = _e171;
    }
    let _e173 = phi_2324_;
    return _e173;
}

fn mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_15: ptr<function, MxcLobe>, woLocal: ptr<function, vec3<f32>>, ms_1: ptr<function, vec3<f32>>) -> f32 {
    var param_161: MxcLobe;
    var param_162: vec3<f32>;
    var param_163: vec3<f32>;
    var param_164: vec3<f32>;

    let _e132 = (*l_15).weight;
    if all((_e132 == vec3<f32>(0f, 0f, 0f))) {
        return 0f;
    }
    let _e136 = (*l_15).weight;
    let _e137 = (*l_15);
    param_161 = _e137;
    let _e138 = (*woLocal);
    param_162 = _e138;
    let _e139 = (*ms_1);
    param_163 = _e139;
    let _e140 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_161), (&param_162), (&param_163));
    param_164 = (_e136 * _e140);
    let _e142 = mxc_luminance_u0028_vf3_u003b((&param_164));
    return (max(_e142, 0f) + 0.0001f);
}

fn mxc_walk_texel_u0028_f1_u003b_f1_u003b(column: ptr<function, f32>, row: ptr<function, f32>) -> f32 {
    var t_4: vec2<f32>;

    let _e127 = (*column);
    let _e129 = (*row);
    t_4 = (vec2<f32>((_e127 + 0.5f), (_e129 + 0.5f)) / vec2<f32>(32f, 2070f));
    let _e133 = t_4;
    let _e134 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, _e133, 0f);
    return _e134.x;
}

fn mxc_walk_eta_index_u0028_f1_u003b(eta_3: ptr<function, f32>) -> f32 {
    var e_3: f32;

    let _e126 = (*eta_3);
    e_3 = max(_e126, 1f);
    let _e128 = e_3;
    let _e131 = e_3;
    return (clamp(((2f * (_e128 - 1f)) / (_e131 + 1f)), 0f, 1f) * 12f);
}

fn mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b(mu_9: ptr<function, f32>, alpha_13: ptr<function, f32>, eta_4: ptr<function, f32>) -> f32 {
    var fe: f32;
    var param_165: f32;
    var e0_: f32;
    var column_1: f32;
    var row_1: f32;
    var a_6: f32;
    var param_166: f32;
    var param_167: f32;
    var b_3: f32;
    var param_168: f32;
    var param_169: f32;

    let _e138 = (*eta_4);
    param_165 = _e138;
    let _e139 = mxc_walk_eta_index_u0028_f1_u003b((&param_165));
    fe = _e139;
    let _e140 = fe;
    e0_ = min(floor(_e140), 11f);
    let _e143 = (*mu_9);
    column_1 = (sqrt(clamp(_e143, 0f, 1f)) * 31f);
    let _e147 = (*alpha_13);
    row_1 = (1654f + (sqrt(clamp(_e147, 0f, 1f)) * 31f));
    let _e152 = row_1;
    let _e153 = e0_;
    let _e156 = column_1;
    param_166 = _e156;
    param_167 = (_e152 + (_e153 * 32f));
    let _e157 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_166), (&param_167));
    a_6 = _e157;
    let _e158 = row_1;
    let _e159 = e0_;
    let _e163 = column_1;
    param_168 = _e163;
    param_169 = (_e158 + ((_e159 + 1f) * 32f));
    let _e164 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_168), (&param_169));
    b_3 = _e164;
    let _e165 = a_6;
    let _e166 = b_3;
    let _e167 = fe;
    let _e168 = e0_;
    return mix(_e165, _e166, (_e167 - _e168));
}

fn mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_16: ptr<function, MxcLobe>, wo_14: ptr<function, vec3<f32>>, ms_2: ptr<function, vec3<f32>>) -> f32 {
    var param_170: vec2<f32>;
    var param_171: MxcLobe;
    var param_172: MxcLobe;
    var param_173: vec3<f32>;
    var alpha_14: f32;
    var rss: f32;
    var param_174: f32;
    var param_175: f32;
    var param_176: f32;
    var tss: f32;
    var param_177: f32;
    var param_178: f32;
    var param_179: f32;
    var param_180: f32;
    var param_181: f32;
    var param_182: f32;
    var phi_2059_: bool;
    var phi_2065_: bool;
    var phi_2073_: bool;
    var phi_2081_: bool;

    let _e144 = (*l_16).kind;
    let _e145 = (_e144 != 1i);
    phi_2059_ = _e145;
    if !(_e145) {
        let _e148 = (*l_16).alpha;
        param_170 = _e148;
        let _e149 = mxc_is_delta_u0028_vf2_u003b((&param_170));
        phi_2059_ = _e149;
    }
    let _e151 = phi_2059_;
    phi_2065_ = _e151;
    if !(_e151) {
        let _e153 = (*l_16);
        param_171 = _e153;
        let _e154 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_171));
        phi_2065_ = _e154;
    }
    let _e156 = phi_2065_;
    phi_2073_ = _e156;
    if !(_e156) {
        let _e159 = (*l_16).mode;
        phi_2073_ = ((_e159 & 4i) != 0i);
    }
    let _e163 = phi_2073_;
    phi_2081_ = _e163;
    if !(_e163) {
        let _e165 = (*l_16);
        param_172 = _e165;
        let _e166 = (*wo_14);
        param_173 = _e166;
        let _e167 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_172), (&param_173));
        phi_2081_ = !(_e167);
    }
    let _e170 = phi_2081_;
    if _e170 {
        let _e172 = (*ms_2)[0u];
        return _e172;
    }
    let _e175 = (*l_16).alpha[0u];
    let _e178 = (*l_16).alpha[1u];
    alpha_14 = sqrt((_e175 * _e178));
    let _e182 = (*wo_14)[2u];
    param_174 = _e182;
    let _e183 = alpha_14;
    param_175 = _e183;
    let _e185 = (*l_16).eta;
    param_176 = _e185;
    let _e186 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_174), (&param_175), (&param_176));
    rss = _e186;
    let _e188 = (*wo_14)[2u];
    param_177 = _e188;
    let _e189 = alpha_14;
    param_178 = _e189;
    let _e191 = (*l_16).eta;
    param_179 = _e191;
    let _e192 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_177), (&param_178), (&param_179));
    let _e193 = rss;
    tss = (_e192 - _e193);
    let _e196 = (*wo_14)[2u];
    param_180 = _e196;
    let _e197 = alpha_14;
    param_181 = _e197;
    let _e199 = (*l_16).eta;
    param_182 = _e199;
    let _e200 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_180), (&param_181), (&param_182));
    let _e202 = tss;
    return clamp(((1f - _e200) / max(_e202, 0.05f)), 1f, 20f);
}

fn mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_17: ptr<function, MxcLobe>, wo_15: ptr<function, vec3<f32>>) -> vec3<f32> {
    var microfacet: bool;
    var param_183: vec2<f32>;
    var alpha_15: f32;
    var param_184: MxcLobe;
    var param_185: MxcLobe;
    var param_186: vec3<f32>;
    var rss_1: f32;
    var param_187: f32;
    var param_188: f32;
    var param_189: f32;
    var param_190: f32;
    var param_191: f32;
    var param_192: f32;
    var e_4: f32;
    var param_193: MxcLobe;
    var param_194: bool;
    var param_195: f32;
    var param_196: f32;
    var param_197: f32;
    var k_3: vec3<f32>;
    var ab_1: vec2<f32>;
    var param_198: f32;
    var param_199: f32;
    var e_5: f32;
    var param_200: MxcLobe;
    var param_201: f32;
    var param_202: bool;
    var phi_2157_: bool;
    var phi_2164_: bool;
    var phi_2173_: bool;
    var phi_2189_: bool;
    var phi_2201_: bool;

    let _e154 = (*l_17).kind;
    let _e155 = (_e154 == 1i);
    phi_2157_ = _e155;
    if !(_e155) {
        let _e158 = (*l_17).kind;
        phi_2157_ = (_e158 == 2i);
    }
    let _e161 = phi_2157_;
    phi_2164_ = _e161;
    if !(_e161) {
        let _e164 = (*l_17).kind;
        phi_2164_ = (_e164 == 3i);
    }
    let _e167 = phi_2164_;
    microfacet = _e167;
    let _e168 = microfacet;
    let _e169 = !(_e168);
    phi_2173_ = _e169;
    if !(_e169) {
        let _e172 = (*l_17).alpha;
        param_183 = _e172;
        let _e173 = mxc_is_delta_u0028_vf2_u003b((&param_183));
        phi_2173_ = _e173;
    }
    let _e175 = phi_2173_;
    if _e175 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e178 = (*l_17).alpha[0u];
    let _e181 = (*l_17).alpha[1u];
    alpha_15 = sqrt((_e178 * _e181));
    let _e185 = (*l_17).kind;
    let _e186 = (_e185 == 1i);
    phi_2189_ = _e186;
    if _e186 {
        let _e187 = (*l_17);
        param_184 = _e187;
        let _e188 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_184));
        phi_2189_ = _e188;
    }
    let _e190 = phi_2189_;
    if _e190 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e192 = (*l_17).kind;
    let _e193 = (_e192 == 1i);
    phi_2201_ = _e193;
    if _e193 {
        let _e195 = (*l_17).mode;
        phi_2201_ = ((_e195 & 4i) == 0i);
    }
    let _e199 = phi_2201_;
    if _e199 {
        let _e200 = (*l_17);
        param_185 = _e200;
        let _e201 = (*wo_15);
        param_186 = _e201;
        let _e202 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_185), (&param_186));
        if _e202 {
            let _e204 = (*wo_15)[2u];
            param_187 = _e204;
            let _e205 = alpha_15;
            param_188 = _e205;
            let _e207 = (*l_17).eta;
            param_189 = _e207;
            let _e208 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_187), (&param_188), (&param_189));
            rss_1 = _e208;
            let _e210 = (*wo_15)[2u];
            param_190 = _e210;
            let _e211 = alpha_15;
            param_191 = _e211;
            let _e213 = (*l_17).eta;
            param_192 = _e213;
            let _e214 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_190), (&param_191), (&param_192));
            let _e215 = rss_1;
            return vec3(clamp((_e214 / max(_e215, 0.0001f)), 1f, 20f));
        }
        let _e221 = (*wo_15)[2u];
        let _e224 = (*wo_15)[2u];
        let _e226 = (*l_17);
        param_193 = _e226;
        param_194 = (_e224 >= 0f);
        let _e227 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_193), (&param_194));
        param_195 = abs(_e221);
        let _e228 = alpha_15;
        param_196 = _e228;
        param_197 = _e227;
        let _e229 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_195), (&param_196), (&param_197));
        e_4 = _e229;
        let _e230 = e_4;
        k_3 = vec3((1f / max(_e230, 0.05f)));
        let _e234 = k_3;
        return _e234;
    }
    let _e236 = (*wo_15)[2u];
    param_198 = max(_e236, 0f);
    let _e238 = alpha_15;
    param_199 = _e238;
    let _e239 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_198), (&param_199));
    ab_1 = _e239;
    let _e241 = ab_1[0u];
    let _e243 = ab_1[1u];
    e_5 = (_e241 + _e243);
    let _e245 = (*l_17);
    param_200 = _e245;
    param_201 = 1f;
    param_202 = true;
    let _e246 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_200), (&param_201), (&param_202));
    let _e247 = e_5;
    let _e250 = e_5;
    return (vec3(1f) + ((_e246 * (1f - _e247)) / vec3(max(_e250, 0.05f))));
}

fn mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b(c_8: ptr<function, MxcClosure>, wo_16: ptr<function, vec3<f32>>) {
    var k_4: i32;
    var l_18: MxcLobe;
    var o_4: vec3<f32>;
    var param_203: vec3<f32>;
    var param_204: vec3<f32>;
    var param_205: mat3x3<f32>;
    var param_206: vec3<f32>;
    var ms_3: vec3<f32>;
    var param_207: MxcLobe;
    var param_208: vec3<f32>;
    var param_209: MxcLobe;
    var param_210: vec3<f32>;
    var param_211: vec3<f32>;
    var param_212: MxcLobe;
    var param_213: vec3<f32>;
    var param_214: vec3<f32>;
    var param_215: MxcLobe;
    var param_216: vec3<f32>;
    var alpha_16: f32;
    var reflected_1: vec3<f32>;
    var param_217: MxcLobe;
    var param_218: vec3<f32>;
    var param_219: vec3<f32>;
    var addedR: vec3<f32>;
    var param_220: MxcLobe;
    var param_221: vec3<f32>;
    var param_222: vec3<f32>;
    var transmitted_1: vec3<f32>;
    var addedT: vec3<f32>;
    var param_223: MxcLobe;
    var rss_2: f32;
    var param_224: f32;
    var param_225: f32;
    var param_226: f32;
    var param_227: f32;
    var param_228: f32;
    var param_229: f32;
    var mr: MxcLobe;
    var param_230: MxcLobe;
    var param_231: bool;
    var broadR: vec3<f32>;
    var param_232: MxcLobe;
    var param_233: vec3<f32>;
    var param_234: vec3<f32>;
    var broadT: f32;
    var param_235: MxcLobe;
    var mt: MxcLobe;
    var param_236: MxcLobe;
    var param_237: bool;
    var at: f32;
    var param_238: f32;
    var param_239: f32;
    var param_240: f32;
    var param_241: f32;
    var param_242: f32;
    var param_243: f32;
    var total_1: f32;
    var param_244: vec3<f32>;
    var added: f32;
    var param_245: vec3<f32>;
    var local_31: f32;
    var param_246: vec3<f32>;
    var phi_3181_: bool;
    var phi_3221_: bool;

    (*c_8).choiceTotal = 0f;
    k_4 = 0i;
    loop {
        let _e189 = k_4;
        let _e191 = (*c_8).count;
        if (_e189 < _e191) {
            let _e193 = k_4;
            let _e196 = (*c_8).lobes[_e193];
            l_18 = _e196;
            let _e197 = k_4;
            (*c_8).ms[_e197] = vec3<f32>(1f, 1f, 1f);
            let _e200 = k_4;
            (*c_8).msT[_e200] = 1f;
            let _e203 = k_4;
            (*c_8).msLobe[_e203] = vec3<f32>(0f, 0f, 0f);
            let _e206 = k_4;
            (*c_8).msLobeT[_e206] = vec3<f32>(0f, 0f, 0f);
            let _e209 = k_4;
            (*c_8).msPick[_e209] = 0f;
            let _e212 = k_4;
            (*c_8).msSplit[_e212] = 1f;
            let _e215 = k_4;
            (*c_8).choice[_e215] = 0f;
            let _e219 = l_18.weight;
            if all((_e219 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e223 = l_18.N;
            param_203 = _e223;
            let _e225 = l_18.T;
            param_204 = _e225;
            let _e226 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_203), (&param_204));
            param_205 = _e226;
            let _e227 = (*wo_16);
            param_206 = _e227;
            let _e228 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_205), (&param_206));
            o_4 = _e228;
            let _e229 = l_18;
            param_207 = _e229;
            let _e230 = o_4;
            param_208 = _e230;
            let _e231 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_207), (&param_208));
            ms_3 = _e231;
            let _e232 = k_4;
            let _e233 = l_18;
            param_209 = _e233;
            let _e234 = o_4;
            param_210 = _e234;
            let _e235 = ms_3;
            param_211 = _e235;
            let _e236 = mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_209), (&param_210), (&param_211));
            (*c_8).msT[_e232] = _e236;
            let _e239 = k_4;
            let _e240 = l_18;
            param_212 = _e240;
            let _e241 = o_4;
            param_213 = _e241;
            let _e242 = ms_3;
            param_214 = _e242;
            let _e243 = mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_212), (&param_213), (&param_214));
            (*c_8).choice[_e239] = _e243;
            let _e246 = k_4;
            let _e249 = (*c_8).choice[_e246];
            let _e251 = (*c_8).choiceTotal;
            (*c_8).choiceTotal = (_e251 + _e249);
            let _e254 = l_18;
            param_215 = _e254;
            let _e255 = o_4;
            param_216 = _e255;
            let _e256 = mxc_lobe_ms_shaped_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_215), (&param_216));
            if _e256 {
                let _e259 = l_18.alpha[0u];
                let _e262 = l_18.alpha[1u];
                alpha_16 = sqrt((_e259 * _e262));
                let _e265 = l_18;
                param_217 = _e265;
                let _e266 = o_4;
                param_218 = _e266;
                param_219 = vec3<f32>(1f, 1f, 1f);
                let _e267 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_217), (&param_218), (&param_219));
                reflected_1 = _e267;
                let _e268 = l_18;
                param_220 = _e268;
                let _e269 = o_4;
                param_221 = _e269;
                let _e270 = ms_3;
                param_222 = _e270;
                let _e271 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_220), (&param_221), (&param_222));
                let _e272 = reflected_1;
                addedR = max((_e271 - _e272), vec3<f32>(0f, 0f, 0f));
                transmitted_1 = vec3<f32>(0f, 0f, 0f);
                addedT = vec3<f32>(0f, 0f, 0f);
                let _e276 = l_18.kind;
                let _e277 = (_e276 == 1i);
                phi_3181_ = _e277;
                if _e277 {
                    let _e278 = l_18;
                    param_223 = _e278;
                    let _e279 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_223));
                    phi_3181_ = _e279;
                }
                let _e281 = phi_3181_;
                if _e281 {
                    let _e283 = o_4[2u];
                    param_224 = _e283;
                    let _e284 = alpha_16;
                    param_225 = _e284;
                    let _e286 = l_18.eta;
                    param_226 = _e286;
                    let _e287 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_224), (&param_225), (&param_226));
                    rss_2 = _e287;
                    let _e289 = o_4[2u];
                    param_227 = _e289;
                    let _e290 = alpha_16;
                    param_228 = _e290;
                    let _e292 = l_18.eta;
                    param_229 = _e292;
                    let _e293 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_227), (&param_228), (&param_229));
                    let _e294 = rss_2;
                    let _e298 = l_18.c1_;
                    transmitted_1 = (_e298 * max((_e293 - _e294), 0f));
                    let _e300 = k_4;
                    let _e303 = (*c_8).msT[_e300];
                    let _e306 = transmitted_1;
                    addedT = (_e306 * max((_e303 - 1f), 0f));
                }
                let _e308 = l_18;
                param_230 = _e308;
                param_231 = false;
                let _e309 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_230), (&param_231));
                mr = _e309;
                let _e310 = mr;
                param_232 = _e310;
                let _e311 = o_4;
                param_233 = _e311;
                param_234 = vec3<f32>(1f, 1f, 1f);
                let _e312 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_232), (&param_233), (&param_234));
                broadR = _e312;
                broadT = 1f;
                let _e314 = l_18.kind;
                let _e315 = (_e314 == 1i);
                phi_3221_ = _e315;
                if _e315 {
                    let _e316 = l_18;
                    param_235 = _e316;
                    let _e317 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_235));
                    phi_3221_ = _e317;
                }
                let _e319 = phi_3221_;
                if _e319 {
                    let _e320 = l_18;
                    param_236 = _e320;
                    param_237 = true;
                    let _e321 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_236), (&param_237));
                    mt = _e321;
                    let _e324 = mt.alpha[0u];
                    let _e327 = mt.alpha[1u];
                    at = sqrt((_e324 * _e327));
                    let _e331 = o_4[2u];
                    param_238 = _e331;
                    let _e332 = at;
                    param_239 = _e332;
                    let _e334 = l_18.eta;
                    param_240 = _e334;
                    let _e335 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_238), (&param_239), (&param_240));
                    let _e337 = o_4[2u];
                    param_241 = _e337;
                    let _e338 = at;
                    param_242 = _e338;
                    let _e340 = l_18.eta;
                    param_243 = _e340;
                    let _e341 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_241), (&param_242), (&param_243));
                    broadT = (_e335 - _e341);
                }
                let _e343 = k_4;
                let _e344 = addedR;
                let _e345 = broadR;
                (*c_8).msLobe[_e343] = (_e344 / max(_e345, vec3<f32>(0.0001f, 0.0001f, 0.0001f)));
                let _e350 = k_4;
                let _e351 = addedT;
                let _e352 = broadT;
                (*c_8).msLobeT[_e350] = (_e351 / vec3(max(_e352, 0.0001f)));
                let _e358 = reflected_1;
                let _e359 = addedR;
                let _e361 = transmitted_1;
                let _e363 = addedT;
                param_244 = (((_e358 + _e359) + _e361) + _e363);
                let _e365 = mxc_luminance_u0028_vf3_u003b((&param_244));
                total_1 = max(_e365, 0.000001f);
                let _e367 = addedR;
                let _e368 = addedT;
                param_245 = (_e367 + _e368);
                let _e370 = mxc_luminance_u0028_vf3_u003b((&param_245));
                added = _e370;
                let _e371 = k_4;
                let _e372 = added;
                let _e373 = total_1;
                (*c_8).msPick[_e371] = (0.999f * min((_e372 / _e373), 1f));
                let _e379 = k_4;
                let _e380 = added;
                if (_e380 > 0f) {
                    let _e382 = addedR;
                    param_246 = _e382;
                    let _e383 = mxc_luminance_u0028_vf3_u003b((&param_246));
                    let _e384 = added;
                    local_31 = (_e383 / _e384);
                } else {
                    local_31 = 1f;
                }
                let _e386 = local_31;
                (*c_8).msSplit[_e379] = _e386;
                let _e389 = k_4;
                (*c_8).msT[_e389] = 1f;
            } else {
                let _e392 = k_4;
                let _e393 = ms_3;
                (*c_8).ms[_e392] = _e393;
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e396 = k_4;
            k_4 = (_e396 + 1i);
        }
    }
    return;
}

fn mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_19: ptr<function, MxcLobe>, wo_17: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_247: MxcLobe;
    var param_248: vec3<f32>;
    var param_249: MxcLobe;
    var param_250: vec3<f32>;
    var param_251: vec3<f32>;

    let _e131 = (*l_19);
    param_247 = _e131;
    let _e132 = (*wo_17);
    param_248 = _e132;
    let _e133 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_247), (&param_248));
    let _e134 = (*l_19);
    param_249 = _e134;
    let _e135 = (*wo_17);
    param_250 = _e135;
    param_251 = _e133;
    let _e136 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_249), (&param_250), (&param_251));
    return _e136;
}

fn mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_20: ptr<function, MxcLobe>, wo_18: ptr<function, vec3<f32>>) -> vec3<f32> {
    var white: MxcLobe;
    var param_252: MxcLobe;
    var param_253: vec3<f32>;
    var param_254: MxcLobe;
    var param_255: vec3<f32>;
    var phi_2527_: bool;

    let _e132 = (*l_20).kind;
    let _e133 = (_e132 == 9i);
    phi_2527_ = _e133;
    if !(_e133) {
        let _e136 = (*l_20).kind;
        phi_2527_ = (_e136 == 10i);
    }
    let _e139 = phi_2527_;
    if _e139 {
        let _e140 = (*l_20);
        white = _e140;
        white.c0_ = vec3<f32>(1f, 1f, 1f);
        let _e142 = white;
        param_252 = _e142;
        let _e143 = (*wo_18);
        param_253 = _e143;
        let _e144 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_252), (&param_253));
        return _e144;
    }
    let _e145 = (*l_20);
    param_254 = _e145;
    let _e146 = (*wo_18);
    param_255 = _e146;
    let _e147 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_254), (&param_255));
    return _e147;
}

fn mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b(g_1: ptr<function, MxcGeometry>, wo_19: ptr<function, vec3<f32>>, c_9: ptr<function, MxcClosure>) {
    var v5_: vec3<f32>;
    var v6_: vec3<f32>;
    var lobe0_: MxcLobe;
    var e1_: vec3<f32>;
    var param_256: vec3<f32>;
    var param_257: vec3<f32>;
    var param_258: mat3x3<f32>;
    var param_259: vec3<f32>;
    var param_260: MxcLobe;
    var param_261: vec3<f32>;
    var w2_: vec3<f32>;
    var lobe3_: MxcLobe;
    var param_262: MxcClosure;
    var param_263: vec3<f32>;

    let _e142 = (*g_1).N;
    v5_ = _e142;
    let _e144 = (*g_1).T;
    v6_ = _e144;
    (*c_9).emission = vec3<f32>(0f, 0f, 0f);
    (*c_9).transparency = vec3<f32>(0f, 0f, 0f);
    lobe0_.kind = 1i;
    lobe0_.mode = 1i;
    let _e149 = v5_;
    lobe0_.N = _e149;
    let _e151 = v6_;
    lobe0_.T = _e151;
    lobe0_.alpha = vec2<f32>(0.09f, 0.09f);
    lobe0_.eta = 1.5f;
    lobe0_.c0_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.p0_ = 0f;
    lobe0_.p1_ = 1f;
    lobe0_.film = vec3<f32>(0f, 0f, 0f);
    lobe0_.tau = vec3<f32>(0f, 0f, 0f);
    lobe0_.tauEta = 1f;
    let _e164 = lobe0_.N;
    param_256 = _e164;
    let _e166 = lobe0_.T;
    param_257 = _e166;
    let _e167 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_256), (&param_257));
    param_258 = _e167;
    let _e168 = (*wo_19);
    param_259 = _e168;
    let _e169 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_258), (&param_259));
    let _e170 = lobe0_;
    param_260 = _e170;
    param_261 = _e169;
    let _e171 = mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_260), (&param_261));
    e1_ = _e171;
    let _e172 = e1_;
    w2_ = (vec3<f32>(1f, 1f, 1f) - _e172);
    lobe3_.kind = 5i;
    lobe3_.mode = 1i;
    let _e176 = v5_;
    lobe3_.N = _e176;
    let _e179 = (*g_1).T;
    lobe3_.T = _e179;
    lobe3_.alpha = vec2<f32>(0f, 0f);
    lobe3_.eta = 1.5f;
    lobe3_.c0_ = vec3<f32>(0.8f, 0.8f, 0.8f);
    lobe3_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.p0_ = 0f;
    lobe3_.p1_ = 1f;
    lobe3_.film = vec3<f32>(0f, 0f, 0f);
    lobe3_.tau = vec3<f32>(0f, 0f, 0f);
    lobe3_.tauEta = 1f;
    lobe0_.weight = vec3<f32>(1f, 1f, 1f);
    let _e192 = lobe0_;
    (*c_9).lobes[0i] = _e192;
    let _e195 = w2_;
    lobe3_.weight = _e195;
    let _e197 = lobe3_;
    (*c_9).lobes[1i] = _e197;
    (*c_9).count = 2i;
    let _e201 = (*c_9);
    param_262 = _e201;
    let _e202 = (*wo_19);
    param_263 = _e202;
    mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b((&param_262), (&param_263));
    let _e203 = param_262;
    (*c_9) = _e203;
    return;
}

fn mxc_closure_seed_u0028_u1_u003b(seed_1: ptr<function, u32>) {
    return;
}

fn mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b(v_7: ptr<function, vec3<f32>>, fallback: ptr<function, vec3<f32>>) -> vec3<f32> {
    var l2_1: f32;
    var local_32: vec3<f32>;

    let _e128 = (*v_7);
    let _e129 = (*v_7);
    l2_1 = dot(_e128, _e129);
    let _e131 = l2_1;
    if (_e131 > 0.00000000000000000001f) {
        let _e133 = (*v_7);
        let _e134 = l2_1;
        local_32 = (_e133 * inverseSqrt(_e134));
    } else {
        let _e137 = (*fallback);
        local_32 = _e137;
    }
    let _e138 = local_32;
    return _e138;
}

fn main_1() {
    var g_2: MxcGeometry;
    var N_1: vec3<f32>;
    var param_264: vec3<f32>;
    var param_265: vec3<f32>;
    var wo_20: vec3<f32>;
    var param_266: vec3<f32>;
    var param_267: vec3<f32>;
    var facing: f32;
    var handedness: f32;
    var frame_4: mat3x3<f32>;
    var param_268: vec3<f32>;
    var param_269: vec3<f32>;
    var param_270: vec3<f32>;
    var param_271: vec3<f32>;
    var objectFrame: mat3x3<f32>;
    var param_272: vec3<f32>;
    var param_273: vec3<f32>;
    var param_274: u32;
    var param_275: u32;
    var param_276: u32;
    var param_277: u32;
    var c_10: MxcClosure;
    var param_278: MxcGeometry;
    var param_279: vec3<f32>;
    var param_280: MxcClosure;
    var radiance: vec3<f32>;
    var lights: i32;
    var kinds: i32;
    var image: bool;
    var n_1: i32;
    var local_33: i32;
    var seed_2: u32;
    var param_281: u32;
    var param_282: u32;
    var param_283: u32;
    var pixel: u32;
    var param_284: u32;
    var param_285: u32;
    var shift: vec4<f32>;
    var param_286: u32;
    var param_287: u32;
    var param_288: u32;
    var param_289: u32;
    var sum: vec3<f32>;
    var b_4: i32;
    var batchLights: i32;
    var batchSamples: i32;
    var local_34: i32;
    var index: u32;
    var choice: vec4<f32>;
    var param_290: u32;
    var param_291: u32;
    var param_292: u32;
    var param_293: u32;
    var param_294: u32;
    var param_295: u32;
    var param_296: u32;
    var param_297: u32;
    var smp: MxcSample;
    var param_298: MxcClosure;
    var param_299: vec3<f32>;
    var param_300: vec3<f32>;
    var above_4: bool;
    var seen: vec3<f32>;
    var local_35: vec3<f32>;
    var local_36: vec3<f32>;
    var param_301: vec3<f32>;
    var param_302: vec3<f32>;
    var param_303: vec3<f32>;
    var w_1: f32;
    var local_37: f32;
    var param_304: vec3<f32>;
    var param_305: f32;
    var param_306: vec3<f32>;
    var param_307: f32;
    var param_308: f32;
    var m_8: vec3<f32>;
    var lightPdf: f32;
    var imageWi: vec3<f32>;
    var imageSeen: vec3<f32>;
    var v_8: vec4<f32>;
    var param_309: u32;
    var param_310: u32;
    var param_311: u32;
    var param_312: vec4<f32>;
    var param_313: f32;
    var param_314: vec3<f32>;
    var param_315: f32;
    var param_316: vec3<f32>;
    var j_2: i32;
    var wi_7: vec3<f32>;
    var incoming: vec3<f32>;
    var use_: bool;
    var strategy: i32;
    var local_38: i32;
    var light: vec4<f32>;
    var directional: bool;
    var param_317: vec3<f32>;
    var param_318: vec3<f32>;
    var d_8: vec3<f32>;
    var d2_: f32;
    var spot: vec4<f32>;
    var f_6: vec3<f32>;
    var pdf_2: f32;
    var param_319: MxcClosure;
    var param_320: vec3<f32>;
    var param_321: vec3<f32>;
    var param_322: bool;
    var param_323: f32;
    var w_2: f32;
    var local_39: f32;
    var param_324: vec3<f32>;
    var param_325: f32;
    var param_326: vec3<f32>;
    var param_327: f32;
    var param_328: f32;
    var w_3: f32;
    var param_329: vec3<f32>;
    var param_330: f32;
    var param_331: f32;
    var coverage: f32;
    var param_332: vec3<f32>;
    var phi_628_: bool;
    var phi_639_: bool;
    var phi_701_: bool;
    var phi_758_: bool;
    var phi_759_: bool;
    var phi_792_: bool;
    var phi_834_: bool;

    let _e246 = vPosition_1;
    g_2.P = _e246;
    let _e248 = vObjectPosition_1;
    g_2.Pobj = _e248;
    let _e250 = vNormal_1;
    param_264 = _e250;
    param_265 = vec3<f32>(0f, 0f, 1f);
    let _e251 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_264), (&param_265));
    N_1 = _e251;
    let _e252 = gl_FrontFacing_1;
    if !(_e252) {
        let _e254 = N_1;
        N_1 = -(_e254);
    }
    let _e257 = mxc_view.eye;
    let _e259 = vPosition_1;
    param_266 = (_e257.xyz - _e259);
    let _e261 = N_1;
    param_267 = _e261;
    let _e262 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_266), (&param_267));
    wo_20 = _e262;
    let _e263 = wo_20;
    let _e264 = N_1;
    facing = dot(_e263, _e264);
    let _e266 = facing;
    if (_e266 < 0.01f) {
        let _e268 = N_1;
        let _e269 = facing;
        let _e271 = wo_20;
        N_1 = normalize((_e268 + (_e271 * (0.01f - _e269))));
    }
    let _e276 = vTangent_1[3u];
    handedness = select(1f, -1f, (_e276 < 0f));
    let _e279 = N_1;
    param_268 = _e279;
    let _e280 = vTangent_1;
    param_269 = _e280.xyz;
    let _e282 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_268), (&param_269));
    frame_4 = _e282;
    let _e283 = N_1;
    g_2.N = _e283;
    let _e286 = frame_4[0];
    g_2.T = _e286;
    let _e289 = frame_4[1];
    let _e290 = handedness;
    g_2.B = (_e289 * _e290);
    let _e293 = vObjectNormal_1;
    param_270 = _e293;
    param_271 = vec3<f32>(0f, 0f, 1f);
    let _e294 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_270), (&param_271));
    g_2.Nobj = _e294;
    let _e297 = g_2.Nobj;
    param_272 = _e297;
    let _e298 = vObjectTangent_1;
    param_273 = _e298;
    let _e299 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_272), (&param_273));
    objectFrame = _e299;
    let _e301 = objectFrame[0];
    g_2.Tobj = _e301;
    let _e304 = objectFrame[1];
    let _e305 = handedness;
    g_2.Bobj = (_e304 * _e305);
    let _e308 = vUv_1;
    g_2.uv = _e308;
    g_2.color = vec4<f32>(1f, 1f, 1f, 1f);
    let _e312 = mxc_view.objectToWorld;
    g_2.objectToWorld = _e312;
    let _e315 = mxc_params.frame;
    g_2.frame = _e315;
    let _e318 = mxc_params.time;
    g_2.time = _e318;
    let _e321 = gl_FragCoord_1[0u];
    let _e324 = gl_FragCoord_1[1u];
    let _e328 = mxc_view.counts[2u];
    param_274 = (bitcast<u32>(_e328) + 7u);
    let _e331 = mxc_pcg_u0028_u1_u003b((&param_274));
    param_275 = (u32(_e324) + _e331);
    let _e333 = mxc_pcg_u0028_u1_u003b((&param_275));
    param_276 = (u32(_e321) ^ _e333);
    let _e335 = mxc_pcg_u0028_u1_u003b((&param_276));
    param_277 = _e335;
    mxc_closure_seed_u0028_u1_u003b((&param_277));
    let _e336 = g_2;
    param_278 = _e336;
    let _e337 = wo_20;
    param_279 = _e337;
    mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b((&param_278), (&param_279), (&param_280));
    let _e338 = param_280;
    c_10 = _e338;
    let _e340 = c_10.emission;
    let _e343 = mxc_view.environment[1u];
    radiance = (_e340 * _e343);
    let _e345 = mxc_light_count_u0028_();
    lights = _e345;
    let _e346 = mxc_light_kinds_u0028_();
    kinds = _e346;
    let _e347 = mxc_environment_code_u0028_();
    image = (_e347 == 3i);
    let _e349 = mxc_environment_code_u0028_();
    if (_e349 != 0i) {
        let _e353 = mxc_view.counts[3u];
        local_33 = max(_e353, 1i);
    } else {
        local_33 = 0i;
    }
    let _e355 = local_33;
    n_1 = _e355;
    let _e357 = gl_FragCoord_1[0u];
    let _e360 = gl_FragCoord_1[1u];
    let _e364 = mxc_view.counts[2u];
    param_281 = bitcast<u32>(_e364);
    let _e366 = mxc_pcg_u0028_u1_u003b((&param_281));
    param_282 = (u32(_e360) + _e366);
    let _e368 = mxc_pcg_u0028_u1_u003b((&param_282));
    param_283 = (u32(_e357) + _e368);
    let _e370 = mxc_pcg_u0028_u1_u003b((&param_283));
    seed_2 = _e370;
    let _e372 = gl_FragCoord_1[0u];
    let _e375 = gl_FragCoord_1[1u];
    param_284 = (u32(_e375) + 2654435769u);
    let _e378 = mxc_pcg_u0028_u1_u003b((&param_284));
    param_285 = (u32(_e372) ^ _e378);
    let _e380 = mxc_pcg_u0028_u1_u003b((&param_285));
    pixel = _e380;
    let _e381 = pixel;
    param_286 = _e381;
    let _e382 = mxc_uniform_u0028_u1_u003b((&param_286));
    let _e383 = param_286;
    pixel = _e383;
    let _e384 = pixel;
    param_287 = _e384;
    let _e385 = mxc_uniform_u0028_u1_u003b((&param_287));
    let _e386 = param_287;
    pixel = _e386;
    let _e387 = pixel;
    param_288 = _e387;
    let _e388 = mxc_uniform_u0028_u1_u003b((&param_288));
    let _e389 = param_288;
    pixel = _e389;
    let _e390 = pixel;
    param_289 = _e390;
    let _e391 = mxc_uniform_u0028_u1_u003b((&param_289));
    let _e392 = param_289;
    pixel = _e392;
    shift = vec4<f32>(_e382, _e385, _e388, _e391);
    sum = vec3<f32>(0f, 0f, 0f);
    b_4 = 0i;
    loop {
        let _e394 = b_4;
        let _e395 = n_1;
        let _e396 = lights;
        if (_e394 < max(_e395, select(0i, 1i, (_e396 > 0i)))) {
            let _e401 = b_4;
            let _e403 = lights;
            batchLights = select(0i, _e403, (_e401 == 0i));
            let _e405 = b_4;
            let _e406 = n_1;
            if (_e405 < _e406) {
                let _e408 = image;
                local_34 = (1i + select(0i, 1i, _e408));
            } else {
                local_34 = 0i;
            }
            let _e411 = local_34;
            batchSamples = _e411;
            let _e414 = mxc_view.counts[2u];
            let _e416 = n_1;
            let _e420 = b_4;
            index = ((bitcast<u32>(_e414) * bitcast<u32>(max(_e416, 1i))) + bitcast<u32>(_e420));
            let _e423 = index;
            param_290 = _e423;
            param_291 = 2u;
            let _e424 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_290), (&param_291));
            let _e425 = index;
            param_292 = _e425;
            param_293 = 3u;
            let _e426 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_292), (&param_293));
            let _e427 = index;
            param_294 = _e427;
            param_295 = 5u;
            let _e428 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_294), (&param_295));
            let _e429 = index;
            param_296 = _e429;
            param_297 = 7u;
            let _e430 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_296), (&param_297));
            let _e432 = shift;
            choice = fract((vec4<f32>(_e424, _e426, _e428, _e430) + _e432));
            smp.valid = false;
            smp.evaluate = false;
            smp.delta = false;
            smp.pdf = 0f;
            smp.weight = vec3<f32>(0f, 0f, 0f);
            let _e440 = N_1;
            smp.wi = _e440;
            let _e442 = n_1;
            if (_e442 > 0i) {
                let _e445 = choice[2u];
                let _e447 = choice[3u];
                let _e449 = choice[0u];
                let _e451 = c_10;
                param_298 = _e451;
                let _e452 = wo_20;
                param_299 = _e452;
                param_300 = vec3<f32>(_e445, _e447, _e449);
                let _e453 = mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b((&param_298), (&param_299), (&param_300));
                smp = _e453;
            }
            let _e455 = smp.wi;
            let _e456 = N_1;
            above_4 = (dot(_e455, _e456) > 0f);
            let _e460 = smp.valid;
            if _e460 {
                let _e461 = above_4;
                if _e461 {
                    let _e463 = smp.wi;
                    local_36 = _e463;
                } else {
                    let _e464 = wo_20;
                    param_301 = -(_e464);
                    let _e467 = smp.wi;
                    param_302 = _e467;
                    let _e468 = mxc_exit_direction_u0028_vf3_u003b_vf3_u003b((&param_301), (&param_302));
                    local_36 = _e468;
                }
                let _e469 = local_36;
                param_303 = _e469;
                let _e470 = mxc_environment_u0028_vf3_u003b((&param_303));
                local_35 = _e470;
            } else {
                local_35 = vec3<f32>(0f, 0f, 0f);
            }
            let _e471 = local_35;
            seen = _e471;
            let _e472 = b_4;
            let _e473 = n_1;
            let _e476 = smp.valid;
            let _e477 = ((_e472 < _e473) && _e476);
            phi_628_ = _e477;
            if _e477 {
                let _e479 = smp.evaluate;
                phi_628_ = !(_e479);
            }
            let _e482 = phi_628_;
            if _e482 {
                let _e483 = image;
                let _e484 = above_4;
                let _e485 = (_e483 && _e484);
                phi_639_ = _e485;
                if _e485 {
                    let _e487 = smp.delta;
                    phi_639_ = !(_e487);
                }
                let _e490 = phi_639_;
                if _e490 {
                    let _e492 = smp.wi;
                    param_304 = _e492;
                    let _e495 = mxc_view.environment[2u];
                    param_305 = _e495;
                    let _e496 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_304), (&param_305));
                    param_306 = _e496;
                    let _e497 = mxc_env_pdf_u0028_vf3_u003b((&param_306));
                    let _e499 = smp.pdf;
                    param_307 = _e499;
                    param_308 = _e497;
                    let _e500 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_307), (&param_308));
                    local_37 = _e500;
                } else {
                    local_37 = 1f;
                }
                let _e501 = local_37;
                w_1 = _e501;
                let _e502 = w_1;
                let _e504 = smp.weight;
                let _e506 = seen;
                let _e508 = sum;
                sum = (_e508 + ((_e504 * _e502) * _e506));
            }
            m_8 = vec3<f32>(0f, 0f, 0f);
            lightPdf = 0f;
            let _e510 = N_1;
            imageWi = _e510;
            imageSeen = vec3<f32>(0f, 0f, 0f);
            let _e511 = image;
            let _e512 = b_4;
            let _e513 = n_1;
            if (_e511 && (_e512 < _e513)) {
                let _e517 = choice[1u];
                let _e518 = seed_2;
                param_309 = _e518;
                let _e519 = mxc_uniform_u0028_u1_u003b((&param_309));
                let _e520 = param_309;
                seed_2 = _e520;
                let _e521 = seed_2;
                param_310 = _e521;
                let _e522 = mxc_uniform_u0028_u1_u003b((&param_310));
                let _e523 = param_310;
                seed_2 = _e523;
                let _e524 = seed_2;
                param_311 = _e524;
                let _e525 = mxc_uniform_u0028_u1_u003b((&param_311));
                let _e526 = param_311;
                seed_2 = _e526;
                v_8 = vec4<f32>(_e517, _e519, _e522, _e525);
                let _e528 = v_8;
                param_312 = _e528;
                let _e529 = mxc_env_sample_u0028_vf4_u003b_f1_u003b((&param_312), (&param_313));
                let _e530 = param_313;
                lightPdf = _e530;
                m_8 = _e529;
                let _e531 = m_8;
                param_314 = _e531;
                let _e534 = mxc_view.environment[2u];
                param_315 = _e534;
                let _e535 = mxc_env_to_world_u0028_vf3_u003b_f1_u003b((&param_314), (&param_315));
                imageWi = _e535;
                let _e536 = lightPdf;
                let _e537 = (_e536 > 0f);
                phi_701_ = _e537;
                if _e537 {
                    let _e538 = imageWi;
                    let _e539 = N_1;
                    phi_701_ = (dot(_e538, _e539) > 0f);
                }
                let _e543 = phi_701_;
                if _e543 {
                    let _e544 = imageWi;
                    param_316 = _e544;
                    let _e545 = mxc_environment_u0028_vf3_u003b((&param_316));
                    imageSeen = _e545;
                }
            }
            j_2 = 0i;
            loop {
                let _e546 = j_2;
                let _e547 = batchLights;
                let _e548 = batchSamples;
                if (_e546 < (_e547 + _e548)) {
                    let _e551 = N_1;
                    wi_7 = _e551;
                    incoming = vec3<f32>(0f, 0f, 0f);
                    use_ = true;
                    let _e552 = n_1;
                    let _e554 = j_2;
                    let _e555 = batchLights;
                    if ((_e552 == 0i) || (_e554 < _e555)) {
                        local_38 = 0i;
                    } else {
                        let _e558 = j_2;
                        let _e559 = batchLights;
                        local_38 = select(2i, 1i, (_e558 == ((_e559 + 1i) - 1i)));
                    }
                    let _e564 = local_38;
                    strategy = _e564;
                    let _e565 = strategy;
                    if (_e565 == 0i) {
                        let _e567 = j_2;
                        let _e570 = mxc_view.lightVector[_e567];
                        light = _e570;
                        let _e571 = j_2;
                        let _e574 = mxc_view.lightRadiance[_e571];
                        incoming = _e574.xyz;
                        let _e576 = kinds;
                        let _e577 = (_e576 == 1i);
                        phi_759_ = _e577;
                        if !(_e577) {
                            let _e579 = kinds;
                            let _e581 = ((_e579 & 1i) != 0i);
                            phi_758_ = _e581;
                            if _e581 {
                                let _e583 = light[3u];
                                phi_758_ = (_e583 == 0f);
                            }
                            let _e586 = phi_758_;
                            phi_759_ = _e586;
                        }
                        let _e588 = phi_759_;
                        directional = _e588;
                        let _e589 = directional;
                        if _e589 {
                            let _e590 = light;
                            param_317 = _e590.xyz;
                            let _e592 = N_1;
                            param_318 = _e592;
                            let _e593 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_317), (&param_318));
                            wi_7 = _e593;
                        } else {
                            let _e594 = light;
                            let _e596 = vPosition_1;
                            d_8 = (_e594.xyz - _e596);
                            let _e598 = d_8;
                            let _e599 = d_8;
                            d2_ = max(dot(_e598, _e599), 0.00000001f);
                            let _e602 = d_8;
                            let _e603 = d2_;
                            wi_7 = (_e602 * inverseSqrt(_e603));
                            let _e606 = d2_;
                            let _e607 = incoming;
                            incoming = (_e607 / vec3(_e606));
                            let _e610 = kinds;
                            let _e612 = ((_e610 & 4i) != 0i);
                            phi_792_ = _e612;
                            if _e612 {
                                let _e614 = light[3u];
                                phi_792_ = (_e614 == 2f);
                            }
                            let _e617 = phi_792_;
                            if _e617 {
                                let _e618 = j_2;
                                let _e621 = mxc_view.lightSpot[_e618];
                                spot = _e621;
                                let _e623 = spot[3u];
                                let _e624 = j_2;
                                let _e628 = mxc_view.lightRadiance[_e624][3u];
                                let _e629 = wi_7;
                                let _e631 = spot;
                                let _e635 = incoming;
                                incoming = (_e635 * smoothstep(_e623, _e628, dot(-(_e629), _e631.xyz)));
                            }
                        }
                    } else {
                        let _e637 = strategy;
                        if (_e637 == 1i) {
                            let _e640 = smp.wi;
                            wi_7 = _e640;
                            let _e641 = seen;
                            incoming = _e641;
                            let _e643 = smp.valid;
                            let _e645 = smp.evaluate;
                            use_ = (_e643 && _e645);
                        } else {
                            let _e647 = imageWi;
                            wi_7 = _e647;
                            let _e648 = imageSeen;
                            incoming = _e648;
                            let _e649 = lightPdf;
                            let _e650 = (_e649 > 0f);
                            phi_834_ = _e650;
                            if _e650 {
                                let _e651 = imageWi;
                                let _e652 = N_1;
                                phi_834_ = (dot(_e651, _e652) > 0f);
                            }
                            let _e656 = phi_834_;
                            use_ = _e656;
                        }
                    }
                    let _e657 = strategy;
                    let _e659 = c_10;
                    param_319 = _e659;
                    let _e660 = wo_20;
                    param_320 = _e660;
                    let _e661 = wi_7;
                    param_321 = _e661;
                    param_322 = (_e657 != 0i);
                    let _e662 = mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b((&param_319), (&param_320), (&param_321), (&param_322), (&param_323));
                    let _e663 = param_323;
                    pdf_2 = _e663;
                    f_6 = _e662;
                    let _e664 = strategy;
                    if (_e664 == 0i) {
                        let _e666 = f_6;
                        let _e667 = incoming;
                        let _e669 = radiance;
                        radiance = (_e669 + (_e666 * _e667));
                    } else {
                        let _e671 = strategy;
                        if (_e671 == 1i) {
                            let _e673 = use_;
                            let _e674 = pdf_2;
                            if (_e673 && (_e674 > 0f)) {
                                let _e677 = image;
                                let _e678 = above_4;
                                if (_e677 && _e678) {
                                    let _e680 = wi_7;
                                    param_324 = _e680;
                                    let _e683 = mxc_view.environment[2u];
                                    param_325 = _e683;
                                    let _e684 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_324), (&param_325));
                                    param_326 = _e684;
                                    let _e685 = mxc_env_pdf_u0028_vf3_u003b((&param_326));
                                    let _e686 = pdf_2;
                                    param_327 = _e686;
                                    param_328 = _e685;
                                    let _e687 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_327), (&param_328));
                                    local_39 = _e687;
                                } else {
                                    local_39 = 1f;
                                }
                                let _e688 = local_39;
                                w_2 = _e688;
                                let _e689 = w_2;
                                let _e690 = f_6;
                                let _e692 = pdf_2;
                                let _e695 = incoming;
                                let _e697 = sum;
                                sum = (_e697 + (((_e690 * _e689) / vec3(_e692)) * _e695));
                            }
                        } else {
                            let _e699 = use_;
                            if _e699 {
                                let _e700 = m_8;
                                param_329 = _e700;
                                let _e701 = mxc_env_pdf_u0028_vf3_u003b((&param_329));
                                param_330 = _e701;
                                let _e702 = pdf_2;
                                param_331 = _e702;
                                let _e703 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_330), (&param_331));
                                w_3 = _e703;
                                let _e704 = w_3;
                                let _e705 = f_6;
                                let _e707 = incoming;
                                let _e709 = lightPdf;
                                let _e712 = sum;
                                sum = (_e712 + (((_e705 * _e704) * _e707) / vec3(_e709)));
                            }
                        }
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e714 = j_2;
                    j_2 = (_e714 + 1i);
                }
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e716 = b_4;
            b_4 = (_e716 + 1i);
        }
    }
    let _e718 = sum;
    let _e719 = n_1;
    let _e724 = radiance;
    radiance = (_e724 + (_e718 / vec3(f32(max(_e719, 1i)))));
    let _e727 = c_10.transparency;
    param_332 = _e727;
    let _e728 = mxc_luminance_u0028_vf3_u003b((&param_332));
    coverage = (1f - clamp(_e728, 0f, 1f));
    let _e731 = radiance;
    let _e732 = coverage;
    outColor = vec4<f32>(_e731.x, _e731.y, _e731.z, _e732);
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
