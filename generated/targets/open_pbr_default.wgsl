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
    let _e119 = (*c);
    return dot(_e119, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l: ptr<function, MxcLobe>) -> bool {
    return false;
}

fn mxc_mean_u0028_vf3_u003b(c_1: ptr<function, vec3<f32>>) -> f32 {
    let _e120 = (*c_1)[0u];
    let _e122 = (*c_1)[1u];
    let _e125 = (*c_1)[2u];
    return (((_e120 + _e122) + _e125) * 0.33333334f);
}

fn mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b(cosi: ptr<function, f32>, eta: ptr<function, f32>) -> f32 {
    var sin2t: f32;
    var cost: f32;
    var rs: f32;
    var rp: f32;

    let _e124 = (*eta);
    if (abs((_e124 - 1f)) < 0.000001f) {
        return 0f;
    }
    let _e128 = (*cosi);
    let _e129 = (*cosi);
    let _e132 = (*eta);
    let _e133 = (*eta);
    sin2t = ((1f - (_e128 * _e129)) / (_e132 * _e133));
    let _e136 = sin2t;
    if (_e136 >= 1f) {
        return 1f;
    }
    let _e138 = sin2t;
    cost = sqrt((1f - _e138));
    let _e141 = (*cosi);
    let _e142 = (*eta);
    let _e143 = cost;
    let _e146 = (*cosi);
    let _e147 = (*eta);
    let _e148 = cost;
    rs = ((_e141 - (_e142 * _e143)) / (_e146 + (_e147 * _e148)));
    let _e152 = (*eta);
    let _e153 = (*cosi);
    let _e155 = cost;
    let _e157 = (*eta);
    let _e158 = (*cosi);
    let _e160 = cost;
    rp = (((_e152 * _e153) - _e155) / ((_e157 * _e158) + _e160));
    let _e163 = rs;
    let _e164 = rs;
    let _e166 = rp;
    let _e167 = rp;
    return (0.5f * ((_e163 * _e164) + (_e166 * _e167)));
}

fn mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_1: ptr<function, MxcLobe>, above: ptr<function, bool>) -> f32 {
    var local: f32;

    let _e121 = (*above);
    if _e121 {
        let _e123 = (*l_1).eta;
        local = _e123;
    } else {
        let _e125 = (*l_1).eta;
        local = (1f / _e125);
    }
    let _e127 = local;
    return _e127;
}

fn mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b(l_2: ptr<function, MxcLobe>, cosh_: ptr<function, f32>, above_1: ptr<function, bool>) -> vec3<f32> {
    var f: vec3<f32>;
    var param: MxcLobe;
    var param_1: bool;
    var param_2: f32;
    var param_3: f32;

    f = vec3<f32>(1f, 1f, 1f);
    let _e127 = (*l_2).kind;
    if (_e127 == 1i) {
        let _e129 = (*l_2);
        param = _e129;
        let _e130 = (*above_1);
        param_1 = _e130;
        let _e131 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param), (&param_1));
        let _e132 = (*cosh_);
        param_2 = _e132;
        param_3 = _e131;
        let _e133 = mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b((&param_2), (&param_3));
        f = vec3(_e133);
    }
    let _e135 = f;
    return _e135;
}

fn mxc_rough_alpha_u0028_vf2_u003b(alpha: ptr<function, vec2<f32>>) -> vec2<f32> {
    let _e119 = (*alpha);
    return max(_e119, vec2<f32>(0.0001f, 0.0001f));
}

fn mxc_ggx_d_u0028_vf3_u003b_vf2_u003b(m: ptr<function, vec3<f32>>, alpha_1: ptr<function, vec2<f32>>) -> f32 {
    var param_4: vec2<f32>;
    var s: vec3<f32>;
    var d: f32;

    let _e124 = (*m)[2u];
    if (_e124 <= 0f) {
        return 0f;
    }
    let _e126 = (*alpha_1);
    param_4 = _e126;
    let _e127 = mxc_rough_alpha_u0028_vf2_u003b((&param_4));
    (*alpha_1) = _e127;
    let _e129 = (*m)[0u];
    let _e131 = (*alpha_1)[0u];
    let _e134 = (*m)[1u];
    let _e136 = (*alpha_1)[1u];
    let _e139 = (*m)[2u];
    s = vec3<f32>((_e129 / _e131), (_e134 / _e136), _e139);
    let _e141 = s;
    let _e142 = s;
    d = dot(_e141, _e142);
    let _e145 = (*alpha_1)[0u];
    let _e148 = (*alpha_1)[1u];
    let _e150 = d;
    let _e152 = d;
    return (1f / ((((3.1415927f * _e145) * _e148) * _e150) * _e152));
}

fn mxc_sqr_u0028_f1_u003b(x: ptr<function, f32>) -> f32 {
    let _e119 = (*x);
    let _e120 = (*x);
    return (_e119 * _e120);
}

fn mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b(v: ptr<function, vec3<f32>>, alpha_2: ptr<function, vec2<f32>>) -> f32 {
    var param_5: vec2<f32>;
    var z2_: f32;
    var a2_: f32;
    var param_6: f32;
    var param_7: f32;

    let _e125 = (*alpha_2);
    param_5 = _e125;
    let _e126 = mxc_rough_alpha_u0028_vf2_u003b((&param_5));
    (*alpha_2) = _e126;
    let _e128 = (*v)[2u];
    let _e130 = (*v)[2u];
    z2_ = (_e128 * _e130);
    let _e132 = z2_;
    if (_e132 <= 0f) {
        return 10000000000f;
    }
    let _e135 = (*alpha_2)[0u];
    let _e137 = (*v)[0u];
    param_6 = (_e135 * _e137);
    let _e139 = mxc_sqr_u0028_f1_u003b((&param_6));
    let _e141 = (*alpha_2)[1u];
    let _e143 = (*v)[1u];
    param_7 = (_e141 * _e143);
    let _e145 = mxc_sqr_u0028_f1_u003b((&param_7));
    let _e147 = z2_;
    a2_ = ((_e139 + _e145) / _e147);
    let _e149 = a2_;
    return (0.5f * (-1f + sqrt((1f + _e149))));
}

fn mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b(v_1: ptr<function, vec3<f32>>, alpha_3: ptr<function, vec2<f32>>) -> f32 {
    var param_8: vec3<f32>;
    var param_9: vec2<f32>;

    let _e122 = (*v_1);
    param_8 = _e122;
    let _e123 = (*alpha_3);
    param_9 = _e123;
    let _e124 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_8), (&param_9));
    return (1f / (1f + _e124));
}

fn mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo: ptr<function, vec3<f32>>, m_1: ptr<function, vec3<f32>>, alpha_4: ptr<function, vec2<f32>>) -> f32 {
    var param_10: vec3<f32>;
    var param_11: vec2<f32>;
    var param_12: vec3<f32>;
    var param_13: vec2<f32>;

    let _e126 = (*wo)[2u];
    if (_e126 <= 0f) {
        return 0f;
    }
    let _e128 = (*wo);
    param_10 = _e128;
    let _e129 = (*alpha_4);
    param_11 = _e129;
    let _e130 = mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b((&param_10), (&param_11));
    let _e131 = (*wo);
    let _e132 = (*m_1);
    let _e136 = (*m_1);
    param_12 = _e136;
    let _e137 = (*alpha_4);
    param_13 = _e137;
    let _e138 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_12), (&param_13));
    let _e141 = (*wo)[2u];
    return (((_e130 * max(dot(_e131, _e132), 0f)) * _e138) / _e141);
}

fn mxc_is_delta_u0028_vf2_u003b(alpha_5: ptr<function, vec2<f32>>) -> bool {
    let _e120 = (*alpha_5)[0u];
    let _e122 = (*alpha_5)[1u];
    return (max(_e120, _e122) < 0.0001f);
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
    var phi_2571_: bool;
    var phi_2652_: bool;

    let _e140 = (*l_3).kind;
    switch _e140 {
        case 2, 3, 1: {
            let _e154 = (*l_3).alpha;
            param_14 = _e154;
            let _e155 = mxc_is_delta_u0028_vf2_u003b((&param_14));
            if _e155 {
                return 0f;
            }
            let _e157 = (*wo_1)[2u];
            above_2 = (_e157 > 0f);
            let _e159 = above_2;
            if _e159 {
                let _e160 = (*wo_1);
                local_1 = _e160;
            } else {
                let _e161 = (*wo_1);
                local_1 = -(_e161);
            }
            let _e163 = local_1;
            o = _e163;
            let _e164 = above_2;
            if _e164 {
                let _e165 = (*wi);
                local_2 = _e165;
            } else {
                let _e166 = (*wi);
                local_2 = -(_e166);
            }
            let _e168 = local_2;
            i = _e168;
            let _e170 = i[2u];
            if (_e170 > 0f) {
                let _e172 = o;
                let _e173 = i;
                h = normalize((_e172 + _e173));
                let _e176 = o;
                param_15 = _e176;
                let _e177 = h;
                param_16 = _e177;
                let _e179 = (*l_3).alpha;
                param_17 = _e179;
                let _e180 = mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_15), (&param_16), (&param_17));
                let _e181 = o;
                let _e182 = h;
                p = (_e180 / (4f * max(dot(_e181, _e182), 0.000001f)));
                let _e188 = (*l_3).kind;
                if (_e188 == 2i) {
                    let _e190 = p;
                    return _e190;
                }
                let _e192 = (*l_3).mode;
                if ((_e192 & 1i) == 0i) {
                    return 0f;
                }
                let _e195 = o;
                let _e196 = h;
                let _e199 = (*l_3);
                param_18 = _e199;
                param_19 = max(dot(_e195, _e196), 0f);
                let _e200 = above_2;
                param_20 = _e200;
                let _e201 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_18), (&param_19), (&param_20));
                param_21 = _e201;
                let _e202 = mxc_mean_u0028_vf3_u003b((&param_21));
                fr = _e202;
                let _e203 = p;
                let _e204 = (*l_3);
                param_22 = _e204;
                let _e205 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_22));
                phi_2652_ = _e205;
                if _e205 {
                    let _e207 = (*l_3).mode;
                    phi_2652_ = ((_e207 & 1i) != 0i);
                }
                let _e211 = phi_2652_;
                let _e212 = fr;
                return (_e203 * select(1f, _e212, _e211));
            }
            return 0f;
        }
        default: {
            let _e142 = (*wo_1)[2u];
            let _e143 = (_e142 > 0f);
            phi_2571_ = _e143;
            if _e143 {
                let _e145 = (*wi)[2u];
                phi_2571_ = (_e145 > 0f);
            }
            let _e148 = phi_2571_;
            if _e148 {
                let _e150 = (*wi)[2u];
                local_3 = (_e150 * 0.31830987f);
            } else {
                local_3 = 0f;
            }
            let _e152 = local_3;
            return _e152;
        }
    }
}

fn mxc_safe_sqrt_u0028_f1_u003b(x_1: ptr<function, f32>) -> f32 {
    let _e119 = (*x_1);
    return sqrt(max(_e119, 0f));
}

fn mxc_fon_albedo_u0028_f1_u003b_f1_u003b(sigma: ptr<function, f32>, mu: ptr<function, f32>) -> f32 {
    var a: f32;
    var c_2: f32;
    var s_1: f32;
    var param_23: f32;
    var theta: f32;
    var tail: f32;
    var local_4: f32;
    var g: f32;

    let _e128 = (*sigma);
    a = (1f / (1f + (0.2877934f * _e128)));
    let _e132 = (*mu);
    c_2 = clamp(_e132, 0f, 1f);
    let _e134 = c_2;
    let _e135 = c_2;
    param_23 = (1f - (_e134 * _e135));
    let _e138 = mxc_safe_sqrt_u0028_f1_u003b((&param_23));
    s_1 = _e138;
    let _e139 = c_2;
    theta = acos(_e139);
    let _e141 = c_2;
    if (_e141 > 0.0001f) {
        let _e143 = s_1;
        let _e144 = s_1;
        let _e146 = s_1;
        let _e149 = c_2;
        local_4 = ((1f - ((_e143 * _e144) * _e146)) / _e149);
    } else {
        let _e151 = c_2;
        local_4 = (1.5f * _e151);
    }
    let _e153 = local_4;
    tail = _e153;
    let _e154 = s_1;
    let _e155 = theta;
    let _e156 = s_1;
    let _e157 = c_2;
    let _e161 = s_1;
    let _e163 = tail;
    let _e166 = s_1;
    g = (((_e154 * (_e155 - (_e156 * _e157))) + ((0.6666667f * _e161) * _e163)) - (0.6666667f * _e166));
    let _e169 = a;
    let _e170 = (*sigma);
    let _e171 = a;
    let _e173 = g;
    return (_e169 + (((_e170 * _e171) * _e173) * 0.31830987f));
}

fn mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b(sigma_1: ptr<function, f32>, wo_2: ptr<function, vec3<f32>>, wi_1: ptr<function, vec3<f32>>) -> f32 {
    var a_1: f32;
    var s_2: f32;
    var t: f32;
    var local_5: f32;

    let _e125 = (*sigma_1);
    a_1 = (1f / (1f + (0.2877934f * _e125)));
    let _e129 = (*wi_1);
    let _e130 = (*wo_2);
    let _e133 = (*wi_1)[2u];
    let _e135 = (*wo_2)[2u];
    s_2 = (dot(_e129, _e130) - (_e133 * _e135));
    let _e138 = s_2;
    if (_e138 > 0f) {
        let _e141 = (*wi_1)[2u];
        let _e143 = (*wo_2)[2u];
        local_5 = max(max(_e141, _e143), 0.000001f);
    } else {
        local_5 = 1f;
    }
    let _e146 = local_5;
    t = _e146;
    let _e147 = a_1;
    let _e148 = (*sigma_1);
    let _e149 = a_1;
    let _e151 = s_2;
    let _e153 = t;
    return ((_e147 + (((_e148 * _e149) * _e151) / _e153)) * 0.31830987f);
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

    let _e133 = (*rho);
    let _e134 = (*sigma_2);
    param_24 = _e134;
    let _e135 = (*wo_3);
    param_25 = _e135;
    let _e136 = (*wi_2);
    param_26 = _e136;
    let _e137 = mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b((&param_24), (&param_25), (&param_26));
    f_1 = (_e133 * _e137);
    let _e139 = (*sigma_2);
    a_2 = (1f / (1f + (0.2877934f * _e139)));
    let _e143 = a_2;
    let _e144 = (*sigma_2);
    eavg = (_e143 * (1f + (0.07248821f * _e144)));
    let _e148 = eavg;
    if (_e148 < 0.999999f) {
        let _e150 = (*rho);
        let _e151 = (*rho);
        let _e153 = eavg;
        let _e155 = eavg;
        let _e159 = (*rho);
        let _e160 = eavg;
        rhoMs = ((((_e150 * _e151) * _e153) / vec3((1f - _e155))) / (vec3(1f) - (_e159 * (1f - _e160))));
        let _e166 = rhoMs;
        let _e167 = (*sigma_2);
        param_27 = _e167;
        let _e169 = (*wi_2)[2u];
        param_28 = _e169;
        let _e170 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_27), (&param_28));
        let _e173 = (*sigma_2);
        param_29 = _e173;
        let _e175 = (*wo_3)[2u];
        param_30 = _e175;
        let _e176 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_29), (&param_30));
        let _e180 = f_1;
        f_1 = (_e180 + (((_e166 * (1f - _e170)) * (1f - _e176)) * 0.31830987f));
    }
    let _e182 = f_1;
    return _e182;
}

fn mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo_4: ptr<function, vec3<f32>>, wi_3: ptr<function, vec3<f32>>, alpha_6: ptr<function, vec2<f32>>) -> f32 {
    var param_31: vec3<f32>;
    var param_32: vec2<f32>;
    var param_33: vec3<f32>;
    var param_34: vec2<f32>;

    let _e125 = (*wo_4);
    param_31 = _e125;
    let _e126 = (*alpha_6);
    param_32 = _e126;
    let _e127 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_31), (&param_32));
    let _e129 = (*wi_3);
    param_33 = _e129;
    let _e130 = (*alpha_6);
    param_34 = _e130;
    let _e131 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_33), (&param_34));
    return (1f / ((1f + _e127) + _e131));
}

fn mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_4: ptr<function, MxcLobe>, wo_5: ptr<function, vec3<f32>>, wi_4: ptr<function, vec3<f32>>) -> vec3<f32> {
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
    var phi_1783_: bool;
    var phi_1790_: bool;

    let _e133 = (*wo_5)[2u];
    let _e134 = (_e133 <= 0f);
    phi_1783_ = _e134;
    if !(_e134) {
        let _e137 = (*wi_4)[2u];
        phi_1783_ = (_e137 <= 0f);
    }
    let _e140 = phi_1783_;
    phi_1790_ = _e140;
    if !(_e140) {
        let _e143 = (*l_4).alpha;
        param_35 = _e143;
        let _e144 = mxc_is_delta_u0028_vf2_u003b((&param_35));
        phi_1790_ = _e144;
    }
    let _e146 = phi_1790_;
    if _e146 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e147 = (*wo_5);
    let _e148 = (*wi_4);
    h_1 = normalize((_e147 + _e148));
    let _e151 = (*wo_5);
    let _e152 = h_1;
    let _e155 = (*l_4);
    param_36 = _e155;
    param_37 = max(dot(_e151, _e152), 0f);
    param_38 = true;
    let _e156 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_36), (&param_37), (&param_38));
    f_2 = _e156;
    let _e158 = (*l_4).kind;
    if (_e158 == 1i) {
        let _e161 = (*l_4).c0_;
        let _e162 = f_2;
        f_2 = (_e162 * _e161);
    }
    let _e164 = f_2;
    let _e165 = h_1;
    param_39 = _e165;
    let _e167 = (*l_4).alpha;
    param_40 = _e167;
    let _e168 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_39), (&param_40));
    let _e170 = (*wo_5);
    param_41 = _e170;
    let _e171 = (*wi_4);
    param_42 = _e171;
    let _e173 = (*l_4).alpha;
    param_43 = _e173;
    let _e174 = mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_41), (&param_42), (&param_43));
    let _e177 = (*wo_5)[2u];
    return (((_e164 * _e168) * _e174) / vec3((4f * _e177)));
}

fn mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_5: ptr<function, MxcLobe>, wo_6: ptr<function, vec3<f32>>, wi_5: ptr<function, vec3<f32>>) -> vec3<f32> {
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
    var phi_2505_: bool;
    var phi_2520_: bool;

    let _e137 = (*l_5).kind;
    switch _e137 {
        case 1: {
            let _e139 = (*wo_6)[2u];
            let _e141 = (*wi_5)[2u];
            if ((_e139 * _e141) > 0f) {
                let _e145 = (*l_5).mode;
                if ((_e145 & 1i) == 0i) {
                    return vec3<f32>(0f, 0f, 0f);
                }
                let _e149 = (*wo_6)[2u];
                if (_e149 < 0f) {
                    let _e151 = (*l_5);
                    m_2 = _e151;
                    let _e153 = (*l_5).eta;
                    m_2.eta = (1f / _e153);
                    m_2.c0_ = vec3<f32>(1f, 1f, 1f);
                    let _e157 = (*wo_6);
                    let _e159 = (*wi_5);
                    let _e161 = m_2;
                    param_44 = _e161;
                    param_45 = -(_e157);
                    param_46 = -(_e159);
                    let _e162 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_44), (&param_45), (&param_46));
                    return _e162;
                }
                let _e163 = (*l_5);
                param_47 = _e163;
                let _e164 = (*wo_6);
                param_48 = _e164;
                let _e165 = (*wi_5);
                param_49 = _e165;
                let _e166 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_47), (&param_48), (&param_49));
                return _e166;
            }
            return vec3<f32>(0f, 0f, 0f);
        }
        case 3, 2: {
            let _e168 = (*l_5).kind;
            let _e169 = (_e168 == 3i);
            phi_2505_ = _e169;
            if _e169 {
                let _e171 = (*l_5).mode;
                phi_2505_ = ((_e171 & 1i) == 0i);
            }
            let _e175 = phi_2505_;
            if _e175 {
                return vec3<f32>(0f, 0f, 0f);
            }
            let _e176 = (*l_5);
            param_50 = _e176;
            let _e177 = (*wo_6);
            param_51 = _e177;
            let _e178 = (*wi_5);
            param_52 = _e178;
            let _e179 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_50), (&param_51), (&param_52));
            return _e179;
        }
        case 5: {
            let _e181 = (*wo_6)[2u];
            let _e182 = (_e181 > 0f);
            phi_2520_ = _e182;
            if _e182 {
                let _e184 = (*wi_5)[2u];
                phi_2520_ = (_e184 > 0f);
            }
            let _e187 = phi_2520_;
            if _e187 {
                let _e189 = (*l_5).c0_;
                param_53 = _e189;
                let _e191 = (*l_5).p0_;
                param_54 = _e191;
                let _e192 = (*wo_6);
                param_55 = _e192;
                let _e193 = (*wi_5);
                param_56 = _e193;
                let _e194 = mxc_eon_u0028_vf3_u003b_f1_u003b_vf3_u003b_vf3_u003b((&param_53), (&param_54), (&param_55), (&param_56));
                let _e196 = (*wi_5)[2u];
                local_6 = (_e194 * _e196);
            } else {
                local_6 = vec3<f32>(0f, 0f, 0f);
            }
            let _e198 = local_6;
            return _e198;
        }
        default: {
            return vec3<f32>(0f, 0f, 0f);
        }
    }
}

fn mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b(l_6: ptr<function, MxcLobe>, mu_1: ptr<function, f32>) -> vec3<f32> {
    return vec3<f32>(1f, 1f, 1f);
}

fn mxc_to_local_u0028_mf33_u003b_vf3_u003b(frame: ptr<function, mat3x3<f32>>, v_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e120 = (*v_2);
    let _e122 = (*frame)[0];
    let _e124 = (*v_2);
    let _e126 = (*frame)[1];
    let _e128 = (*v_2);
    let _e130 = (*frame)[2];
    return vec3<f32>(dot(_e120, _e122), dot(_e124, _e126), dot(_e128, _e130));
}

fn mxc_frame_u0028_vf3_u003b_vf3_u003b(N: ptr<function, vec3<f32>>, T: ptr<function, vec3<f32>>) -> mat3x3<f32> {
    var t_1: vec3<f32>;
    var l2_: f32;
    var s_3: f32;
    var a_3: f32;
    var b: f32;

    let _e125 = (*T);
    let _e126 = (*N);
    let _e127 = (*N);
    let _e128 = (*T);
    t_1 = (_e125 - (_e126 * dot(_e127, _e128)));
    let _e132 = t_1;
    let _e133 = t_1;
    l2_ = dot(_e132, _e133);
    let _e135 = l2_;
    if !((_e135 > 0.000000000001f)) {
        let _e139 = (*N)[2u];
        s_3 = select(-1f, 1f, (_e139 >= 0f));
        let _e142 = s_3;
        let _e144 = (*N)[2u];
        a_3 = (-1f / (_e142 + _e144));
        let _e148 = (*N)[0u];
        let _e150 = (*N)[1u];
        let _e152 = a_3;
        b = ((_e148 * _e150) * _e152);
        let _e154 = s_3;
        let _e156 = (*N)[0u];
        let _e159 = (*N)[0u];
        let _e161 = a_3;
        let _e164 = s_3;
        let _e165 = b;
        let _e167 = s_3;
        let _e170 = (*N)[0u];
        t_1 = vec3<f32>((1f + (((_e154 * _e156) * _e159) * _e161)), (_e164 * _e165), (-(_e167) * _e170));
    } else {
        let _e173 = l2_;
        let _e175 = t_1;
        t_1 = (_e175 * inverseSqrt(_e173));
    }
    let _e177 = t_1;
    let _e178 = (*N);
    let _e179 = t_1;
    let _e180 = cross(_e178, _e179);
    let _e181 = (*N);
    return mat3x3<f32>(vec3<f32>(_e177.x, _e177.y, _e177.z), vec3<f32>(_e180.x, _e180.y, _e180.z), vec3<f32>(_e181.x, _e181.y, _e181.z));
}

fn mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b(c_3: ptr<function, MxcClosure>, wo_7: ptr<function, vec3<f32>>, wi_6: ptr<function, vec3<f32>>, wantPdf: ptr<function, bool>, pdf: ptr<function, f32>) -> vec3<f32> {
    var f_3: vec3<f32>;
    var p_1: f32;
    var k: i32;
    var l_7: MxcLobe;
    var frame_1: mat3x3<f32>;
    var param_57: vec3<f32>;
    var param_58: vec3<f32>;
    var o_1: vec3<f32>;
    var param_59: mat3x3<f32>;
    var param_60: vec3<f32>;
    var i_1: vec3<f32>;
    var param_61: mat3x3<f32>;
    var param_62: vec3<f32>;
    var ms: vec3<f32>;
    var local_7: vec3<f32>;
    var param_63: MxcLobe;
    var param_64: f32;
    var param_65: MxcLobe;
    var param_66: vec3<f32>;
    var param_67: vec3<f32>;
    var param_68: MxcLobe;
    var param_69: vec3<f32>;
    var param_70: vec3<f32>;
    var local_8: f32;

    f_3 = vec3<f32>(0f, 0f, 0f);
    p_1 = 0f;
    k = 0i;
    loop {
        let _e147 = k;
        let _e149 = (*c_3).count;
        if (_e147 < _e149) {
            let _e151 = k;
            let _e154 = (*c_3).lobes[_e151];
            l_7 = _e154;
            let _e156 = l_7.weight;
            if all((_e156 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e160 = l_7.N;
            param_57 = _e160;
            let _e162 = l_7.T;
            param_58 = _e162;
            let _e163 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_57), (&param_58));
            frame_1 = _e163;
            let _e164 = frame_1;
            param_59 = _e164;
            let _e165 = (*wo_7);
            param_60 = _e165;
            let _e166 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_59), (&param_60));
            o_1 = _e166;
            let _e167 = frame_1;
            param_61 = _e167;
            let _e168 = (*wi_6);
            param_62 = _e168;
            let _e169 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_61), (&param_62));
            i_1 = _e169;
            let _e171 = o_1[2u];
            let _e173 = i_1[2u];
            if ((_e171 * _e173) < 0f) {
                let _e176 = k;
                let _e179 = (*c_3).msT[_e176];
                local_7 = vec3(_e179);
            } else {
                let _e181 = k;
                let _e184 = (*c_3).ms[_e181];
                local_7 = _e184;
            }
            let _e185 = local_7;
            ms = _e185;
            let _e187 = l_7.weight;
            let _e188 = ms;
            let _e191 = i_1[2u];
            let _e193 = l_7;
            param_63 = _e193;
            param_64 = abs(_e191);
            let _e194 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_63), (&param_64));
            let _e196 = l_7;
            param_65 = _e196;
            let _e197 = o_1;
            param_66 = _e197;
            let _e198 = i_1;
            param_67 = _e198;
            let _e199 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_65), (&param_66), (&param_67));
            let _e201 = f_3;
            f_3 = (_e201 + (((_e187 * _e188) * _e194) * _e199));
            let _e203 = (*wantPdf);
            if _e203 {
                let _e204 = k;
                let _e207 = (*c_3).choice[_e204];
                let _e208 = l_7;
                param_68 = _e208;
                let _e209 = o_1;
                param_69 = _e209;
                let _e210 = i_1;
                param_70 = _e210;
                let _e211 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_68), (&param_69), (&param_70));
                let _e213 = p_1;
                p_1 = (_e213 + (_e207 * _e211));
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e215 = k;
            k = (_e215 + 1i);
        }
    }
    let _e218 = (*c_3).choiceTotal;
    if (_e218 > 0f) {
        let _e220 = p_1;
        let _e222 = (*c_3).choiceTotal;
        local_8 = (_e220 / _e222);
    } else {
        local_8 = 0f;
    }
    let _e224 = local_8;
    (*pdf) = _e224;
    let _e225 = f_3;
    return _e225;
}

fn mxc_env_to_world_u0028_vf3_u003b_f1_u003b(m_3: ptr<function, vec3<f32>>, angle: ptr<function, f32>) -> vec3<f32> {
    var c_4: f32;
    var s_4: f32;

    let _e122 = (*angle);
    c_4 = cos(_e122);
    let _e124 = (*angle);
    s_4 = sin(_e124);
    let _e126 = c_4;
    let _e128 = (*m_3)[0u];
    let _e130 = s_4;
    let _e132 = (*m_3)[2u];
    let _e136 = (*m_3)[1u];
    let _e137 = s_4;
    let _e140 = (*m_3)[0u];
    let _e142 = c_4;
    let _e144 = (*m_3)[2u];
    return vec3<f32>(((_e126 * _e128) + (_e130 * _e132)), _e136, ((-(_e137) * _e140) + (_e142 * _e144)));
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
    var param_71: f32;

    let _e133 = unnamed.mxc_env_size;
    size = max(_e133.xy, vec2<u32>(1u, 1u));
    let _e137 = size[0u];
    let _e139 = size[1u];
    n = (_e137 * _e139);
    let _e142 = (*u)[0u];
    let _e143 = n;
    let _e147 = n;
    k_1 = min(u32((_e142 * f32(_e143))), (_e147 - 1u));
    let _e150 = k_1;
    let _e153 = unnamed.mxc_env_cells[_e150];
    cell = _e153;
    let _e155 = (*u)[1u];
    let _e157 = cell[0u];
    if (_e155 >= _e157) {
        let _e160 = cell[1u];
        let _e162 = n;
        k_1 = min(bitcast<u32>(_e160), (_e162 - 1u));
    }
    let _e165 = k_1;
    let _e169 = unnamed.mxc_env_cells[_e165][2u];
    (*pdf_1) = _e169;
    let _e170 = k_1;
    let _e172 = size[0u];
    i_2 = (_e170 % _e172);
    let _e174 = k_1;
    let _e176 = size[0u];
    j = (_e174 / _e176);
    let _e178 = i_2;
    let _e181 = (*u)[2u];
    let _e184 = size[0u];
    phi = (6.2831855f * (((f32(_e178) + _e181) / f32(_e184)) - 0.5f));
    let _e189 = j;
    let _e193 = size[1u];
    y0_ = cos(((3.1415927f * f32(_e189)) / f32(_e193)));
    let _e197 = j;
    let _e202 = size[1u];
    y1_ = cos(((3.1415927f * f32((_e197 + 1u))) / f32(_e202)));
    let _e206 = y0_;
    let _e207 = y1_;
    let _e209 = (*u)[3u];
    y = mix(_e206, _e207, _e209);
    let _e211 = y;
    let _e212 = y;
    param_71 = (1f - (_e211 * _e212));
    let _e215 = mxc_safe_sqrt_u0028_f1_u003b((&param_71));
    r = _e215;
    let _e216 = r;
    let _e217 = phi;
    let _e220 = y;
    let _e221 = r;
    let _e223 = phi;
    return vec3<f32>((_e216 * sin(_e217)), _e220, (-(_e221) * cos(_e223)));
}

fn mxc_power_heuristic_u0028_f1_u003b_f1_u003b(a_4: ptr<function, f32>, b_1: ptr<function, f32>) -> f32 {
    var a2_1: f32;
    var b2_: f32;
    var local_9: f32;

    let _e123 = (*a_4);
    let _e124 = (*a_4);
    a2_1 = (_e123 * _e124);
    let _e126 = (*b_1);
    let _e127 = (*b_1);
    b2_ = (_e126 * _e127);
    let _e129 = a2_1;
    let _e130 = b2_;
    if ((_e129 + _e130) > 0f) {
        let _e133 = a2_1;
        let _e134 = a2_1;
        let _e135 = b2_;
        local_9 = (_e133 / (_e134 + _e135));
    } else {
        local_9 = 0f;
    }
    let _e138 = local_9;
    return _e138;
}

fn mxc_env_uv_u0028_vf3_u003b(d_1: ptr<function, vec3<f32>>) -> vec2<f32> {
    var u_1: f32;
    var local_10: f32;
    var v_3: f32;

    let _e123 = (*d_1)[0u];
    let _e126 = (*d_1)[2u];
    if ((abs(_e123) + abs(_e126)) > 0.000000000001f) {
        let _e131 = (*d_1)[0u];
        let _e133 = (*d_1)[2u];
        local_10 = (0.5f + (atan2(_e131, -(_e133)) * 0.15915494f));
    } else {
        local_10 = 0.5f;
    }
    let _e138 = local_10;
    u_1 = _e138;
    let _e139 = (*d_1);
    let _e143 = (*d_1)[1u];
    v_3 = (atan2(length(_e139.xz), _e143) * 0.31830987f);
    let _e146 = u_1;
    let _e147 = v_3;
    return vec2<f32>(_e146, _e147);
}

fn mxc_env_cell_u0028_vf3_u003b(d_2: ptr<function, vec3<f32>>) -> u32 {
    var uv: vec2<f32>;
    var param_72: vec3<f32>;
    var size_1: vec2<u32>;
    var i_3: u32;
    var j_1: u32;

    let _e124 = (*d_2);
    param_72 = _e124;
    let _e125 = mxc_env_uv_u0028_vf3_u003b((&param_72));
    uv = _e125;
    let _e127 = unnamed.mxc_env_size;
    size_1 = max(_e127.xy, vec2<u32>(1u, 1u));
    let _e131 = uv[0u];
    let _e134 = size_1[0u];
    let _e139 = size_1[0u];
    i_3 = min(u32((max(_e131, 0f) * f32(_e134))), (_e139 - 1u));
    let _e143 = uv[1u];
    let _e146 = size_1[1u];
    let _e151 = size_1[1u];
    j_1 = min(u32((max(_e143, 0f) * f32(_e146))), (_e151 - 1u));
    let _e154 = j_1;
    let _e156 = size_1[0u];
    let _e158 = i_3;
    return ((_e154 * _e156) + _e158);
}

fn mxc_env_pdf_u0028_vf3_u003b(d_3: ptr<function, vec3<f32>>) -> f32 {
    var param_73: vec3<f32>;

    let _e120 = (*d_3);
    param_73 = _e120;
    let _e121 = mxc_env_cell_u0028_vf3_u003b((&param_73));
    let _e125 = unnamed.mxc_env_cells[_e121][2u];
    return _e125;
}

fn mxc_env_to_map_u0028_vf3_u003b_f1_u003b(w: ptr<function, vec3<f32>>, angle_1: ptr<function, f32>) -> vec3<f32> {
    var c_5: f32;
    var s_5: f32;

    let _e122 = (*angle_1);
    c_5 = cos(_e122);
    let _e124 = (*angle_1);
    s_5 = sin(_e124);
    let _e126 = c_5;
    let _e128 = (*w)[0u];
    let _e130 = s_5;
    let _e132 = (*w)[2u];
    let _e136 = (*w)[1u];
    let _e137 = s_5;
    let _e139 = (*w)[0u];
    let _e141 = c_5;
    let _e143 = (*w)[2u];
    return vec3<f32>(((_e126 * _e128) - (_e130 * _e132)), _e136, ((_e137 * _e139) + (_e141 * _e143)));
}

fn mxc_env_lookup_u0028_vf3_u003b(d_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_74: vec3<f32>;

    let _e120 = (*d_4);
    param_74 = _e120;
    let _e121 = mxc_env_uv_u0028_vf3_u003b((&param_74));
    let _e122 = textureSampleLevel(mxc_env_radiance_texture, mxc_env_radiance_sampler, _e121, 0f);
    return _e122.xyz;
}

fn mxc_sky_u0028_vf3_u003b(d_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var y_1: f32;
    var horizon: vec3<f32>;
    var zenith: vec3<f32>;
    var ground: vec3<f32>;

    let _e124 = (*d_5)[1u];
    y_1 = clamp(_e124, -1f, 1f);
    horizon = vec3<f32>(1f, 0.96f, 0.9f);
    zenith = vec3<f32>(0.3f, 0.5f, 0.95f);
    ground = vec3<f32>(0.16f, 0.145f, 0.13f);
    let _e126 = y_1;
    if (_e126 >= 0f) {
        let _e128 = horizon;
        let _e129 = zenith;
        let _e130 = y_1;
        return mix(_e128, _e129, vec3(sqrt(_e130)));
    }
    let _e134 = horizon;
    let _e135 = ground;
    let _e136 = y_1;
    return mix(_e134, _e135, vec3(sqrt(-(_e136))));
}

fn mxc_environment_code_u0028_() -> i32 {
    var local_11: i32;

    if false {
        local_11 = MXC_ENVIRONMENT;
    } else {
        let _e121 = mxc_view.counts[1u];
        local_11 = _e121;
    }
    let _e122 = local_11;
    return _e122;
}

fn mxc_environment_u0028_vf3_u003b(d_6: ptr<function, vec3<f32>>) -> vec3<f32> {
    var code: i32;
    var param_75: vec3<f32>;
    var param_76: vec3<f32>;
    var param_77: f32;
    var param_78: vec3<f32>;

    let _e124 = mxc_environment_code_u0028_();
    code = _e124;
    let _e125 = code;
    if (_e125 == 1i) {
        let _e129 = mxc_view.environment[0u];
        return vec3(_e129);
    }
    let _e131 = code;
    if (_e131 == 2i) {
        let _e135 = mxc_view.environment[0u];
        let _e136 = (*d_6);
        param_75 = _e136;
        let _e137 = mxc_sky_u0028_vf3_u003b((&param_75));
        return (_e137 * _e135);
    }
    let _e139 = code;
    if (_e139 == 3i) {
        let _e143 = mxc_view.environment[0u];
        let _e144 = (*d_6);
        param_76 = _e144;
        let _e147 = mxc_view.environment[2u];
        param_77 = _e147;
        let _e148 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_76), (&param_77));
        param_78 = _e148;
        let _e149 = mxc_env_lookup_u0028_vf3_u003b((&param_78));
        return (_e149 * _e143);
    }
    return vec3<f32>(0f, 0f, 0f);
}

fn mxc_exit_direction_u0028_vf3_u003b_vf3_u003b(d_7: ptr<function, vec3<f32>>, t_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var axis: vec3<f32>;
    var s_6: f32;
    var c_6: f32;

    let _e123 = (*d_7);
    let _e124 = (*t_2);
    axis = cross(_e123, _e124);
    let _e126 = axis;
    s_6 = length(_e126);
    let _e128 = s_6;
    if (_e128 < 0.000001f) {
        let _e130 = (*t_2);
        return _e130;
    }
    let _e131 = s_6;
    let _e132 = axis;
    axis = (_e132 / vec3(_e131));
    let _e135 = (*d_7);
    let _e136 = (*t_2);
    c_6 = dot(_e135, _e136);
    let _e138 = (*t_2);
    let _e139 = c_6;
    let _e141 = axis;
    let _e142 = (*t_2);
    let _e144 = s_6;
    let _e147 = axis;
    let _e148 = axis;
    let _e149 = (*t_2);
    let _e152 = c_6;
    return (((_e138 * _e139) + (cross(_e141, _e142) * _e144)) + ((_e147 * dot(_e148, _e149)) * (1f - _e152)));
}

fn mxc_to_world_u0028_mf33_u003b_vf3_u003b(frame_2: ptr<function, mat3x3<f32>>, v_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e121 = (*frame_2)[0];
    let _e123 = (*v_4)[0u];
    let _e126 = (*frame_2)[1];
    let _e128 = (*v_4)[1u];
    let _e132 = (*frame_2)[2];
    let _e134 = (*v_4)[2u];
    return (((_e121 * _e123) + (_e126 * _e128)) + (_e132 * _e134));
}

fn mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b(wo_8: ptr<function, vec3<f32>>, alpha_7: ptr<function, vec2<f32>>, u_2: ptr<function, vec2<f32>>) -> vec3<f32> {
    var param_79: vec2<f32>;
    var vh: vec3<f32>;
    var lensq: f32;
    var t1_: vec3<f32>;
    var local_12: vec3<f32>;
    var t2_: vec3<f32>;
    var r_1: f32;
    var phi_1: f32;
    var p1_: f32;
    var p2_: f32;
    var s_7: f32;
    var param_80: f32;
    var nh: vec3<f32>;
    var param_81: f32;

    let _e135 = (*alpha_7);
    param_79 = _e135;
    let _e136 = mxc_rough_alpha_u0028_vf2_u003b((&param_79));
    (*alpha_7) = _e136;
    let _e138 = (*alpha_7)[0u];
    let _e140 = (*wo_8)[0u];
    let _e143 = (*alpha_7)[1u];
    let _e145 = (*wo_8)[1u];
    let _e148 = (*wo_8)[2u];
    vh = normalize(vec3<f32>((_e138 * _e140), (_e143 * _e145), _e148));
    let _e152 = vh[0u];
    let _e154 = vh[0u];
    let _e157 = vh[1u];
    let _e159 = vh[1u];
    lensq = ((_e152 * _e154) + (_e157 * _e159));
    let _e162 = lensq;
    if (_e162 > 0f) {
        let _e165 = vh[1u];
        let _e168 = vh[0u];
        let _e170 = lensq;
        local_12 = (vec3<f32>(-(_e165), _e168, 0f) * inverseSqrt(_e170));
    } else {
        local_12 = vec3<f32>(1f, 0f, 0f);
    }
    let _e173 = local_12;
    t1_ = _e173;
    let _e174 = vh;
    let _e175 = t1_;
    t2_ = cross(_e174, _e175);
    let _e178 = (*u_2)[0u];
    r_1 = sqrt(_e178);
    let _e181 = (*u_2)[1u];
    phi_1 = (6.2831855f * _e181);
    let _e183 = r_1;
    let _e184 = phi_1;
    p1_ = (_e183 * cos(_e184));
    let _e187 = r_1;
    let _e188 = phi_1;
    p2_ = (_e187 * sin(_e188));
    let _e192 = vh[2u];
    s_7 = (0.5f * (1f + _e192));
    let _e195 = s_7;
    let _e197 = p1_;
    let _e198 = p1_;
    param_80 = (1f - (_e197 * _e198));
    let _e201 = mxc_safe_sqrt_u0028_f1_u003b((&param_80));
    let _e203 = s_7;
    let _e204 = p2_;
    p2_ = (((1f - _e195) * _e201) + (_e203 * _e204));
    let _e207 = p1_;
    let _e208 = t1_;
    let _e210 = p2_;
    let _e211 = t2_;
    let _e214 = p1_;
    let _e215 = p1_;
    let _e218 = p2_;
    let _e219 = p2_;
    param_81 = ((1f - (_e214 * _e215)) - (_e218 * _e219));
    let _e222 = mxc_safe_sqrt_u0028_f1_u003b((&param_81));
    let _e223 = vh;
    nh = (((_e208 * _e207) + (_e211 * _e210)) + (_e223 * _e222));
    let _e227 = (*alpha_7)[0u];
    let _e229 = nh[0u];
    let _e232 = (*alpha_7)[1u];
    let _e234 = nh[1u];
    let _e237 = nh[2u];
    return normalize(vec3<f32>((_e227 * _e229), (_e232 * _e234), max(_e237, 0f)));
}

fn mxc_sample_cosine_u0028_vf2_u003b(u_3: ptr<function, vec2<f32>>) -> vec3<f32> {
    var r_2: f32;
    var phi_2: f32;
    var param_82: f32;

    let _e123 = (*u_3)[0u];
    r_2 = sqrt(_e123);
    let _e126 = (*u_3)[1u];
    phi_2 = (6.2831855f * _e126);
    let _e128 = r_2;
    let _e129 = phi_2;
    let _e132 = r_2;
    let _e133 = phi_2;
    let _e137 = (*u_3)[0u];
    param_82 = (1f - _e137);
    let _e139 = mxc_safe_sqrt_u0028_f1_u003b((&param_82));
    return vec3<f32>((_e128 * cos(_e129)), (_e132 * sin(_e133)), _e139);
}

fn mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_8: ptr<function, MxcLobe>, wo_9: ptr<function, vec3<f32>>, u_4: ptr<function, vec3<f32>>) -> MxcLobeSample {
    var s_8: MxcLobeSample;
    var above_3: bool;
    var o_2: vec3<f32>;
    var local_13: vec3<f32>;
    var delta: bool;
    var param_83: vec2<f32>;
    var m_4: vec3<f32>;
    var local_14: vec3<f32>;
    var param_84: vec3<f32>;
    var param_85: vec2<f32>;
    var param_86: vec2<f32>;
    var hm: f32;
    var transmits: bool;
    var param_87: MxcLobe;
    var reflects: bool;
    var f_4: vec3<f32>;
    var param_88: MxcLobe;
    var param_89: f32;
    var param_90: bool;
    var fr_1: f32;
    var local_15: f32;
    var param_91: vec3<f32>;
    var pReflect: f32;
    var local_16: f32;
    var i_4: vec3<f32>;
    var local_17: vec3<f32>;
    var tint: vec3<f32>;
    var local_18: vec3<f32>;
    var local_19: vec3<f32>;
    var param_92: MxcLobe;
    var param_93: vec3<f32>;
    var param_94: vec3<f32>;
    var param_95: MxcLobe;
    var param_96: vec3<f32>;
    var param_97: vec3<f32>;
    var param_98: vec2<f32>;
    var param_99: MxcLobe;
    var param_100: vec3<f32>;
    var param_101: vec3<f32>;
    var param_102: MxcLobe;
    var param_103: vec3<f32>;
    var param_104: vec3<f32>;
    var phi_2783_: bool;
    var phi_2788_: bool;
    var phi_2799_: bool;

    s_8.valid = false;
    s_8.delta = false;
    s_8.pdf = 0f;
    s_8.value = vec3<f32>(0f, 0f, 0f);
    s_8.wi = vec3<f32>(0f, 0f, 1f);
    let _e169 = (*l_8).kind;
    switch _e169 {
        case 2, 3, 1: {
            let _e196 = (*wo_9)[2u];
            above_3 = (_e196 > 0f);
            let _e198 = above_3;
            if _e198 {
                let _e199 = (*wo_9);
                local_13 = _e199;
            } else {
                let _e200 = (*wo_9);
                local_13 = -(_e200);
            }
            let _e202 = local_13;
            o_2 = _e202;
            let _e204 = o_2[2u];
            if (_e204 <= 0f) {
                let _e206 = s_8;
                return _e206;
            }
            let _e208 = (*l_8).alpha;
            param_83 = _e208;
            let _e209 = mxc_is_delta_u0028_vf2_u003b((&param_83));
            delta = _e209;
            let _e210 = delta;
            if _e210 {
                local_14 = vec3<f32>(0f, 0f, 1f);
            } else {
                let _e211 = o_2;
                param_84 = _e211;
                let _e213 = (*l_8).alpha;
                param_85 = _e213;
                let _e214 = (*u_4);
                param_86 = _e214.xy;
                let _e216 = mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b((&param_84), (&param_85), (&param_86));
                local_14 = _e216;
            }
            let _e217 = local_14;
            m_4 = _e217;
            let _e218 = o_2;
            let _e219 = m_4;
            hm = dot(_e218, _e219);
            let _e222 = (*l_8).kind;
            let _e223 = (_e222 == 1i);
            phi_2783_ = _e223;
            if !(_e223) {
                let _e226 = (*l_8).kind;
                phi_2783_ = (_e226 == 3i);
            }
            let _e229 = phi_2783_;
            phi_2788_ = _e229;
            if _e229 {
                let _e230 = (*l_8);
                param_87 = _e230;
                let _e231 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_87));
                phi_2788_ = _e231;
            }
            let _e233 = phi_2788_;
            transmits = _e233;
            let _e235 = (*l_8).kind;
            let _e236 = (_e235 == 2i);
            phi_2799_ = _e236;
            if !(_e236) {
                let _e239 = (*l_8).mode;
                phi_2799_ = ((_e239 & 1i) != 0i);
            }
            let _e243 = phi_2799_;
            reflects = _e243;
            let _e244 = hm;
            let _e246 = (*l_8);
            param_88 = _e246;
            param_89 = max(_e244, 0f);
            let _e247 = above_3;
            param_90 = _e247;
            let _e248 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_88), (&param_89), (&param_90));
            f_4 = _e248;
            let _e249 = transmits;
            if _e249 {
                let _e250 = f_4;
                param_91 = _e250;
                let _e251 = mxc_mean_u0028_vf3_u003b((&param_91));
                local_15 = _e251;
            } else {
                local_15 = 1f;
            }
            let _e252 = local_15;
            fr_1 = _e252;
            let _e253 = transmits;
            if _e253 {
                let _e254 = reflects;
                let _e255 = fr_1;
                local_16 = select(0f, _e255, _e254);
            } else {
                local_16 = 1f;
            }
            let _e257 = local_16;
            pReflect = _e257;
            let _e259 = (*u_4)[2u];
            let _e260 = pReflect;
            if (_e259 < _e260) {
                let _e262 = o_2;
                let _e264 = m_4;
                i_4 = reflect(-(_e262), _e264);
                let _e267 = i_4[2u];
                if (_e267 <= 0f) {
                    let _e269 = s_8;
                    return _e269;
                }
                let _e270 = above_3;
                if _e270 {
                    let _e271 = i_4;
                    local_17 = _e271;
                } else {
                    let _e272 = i_4;
                    local_17 = -(_e272);
                }
                let _e274 = local_17;
                s_8.wi = _e274;
                let _e276 = delta;
                s_8.delta = _e276;
                let _e278 = delta;
                if _e278 {
                    let _e280 = (*l_8).kind;
                    if (_e280 == 1i) {
                        let _e282 = above_3;
                        if _e282 {
                            let _e284 = (*l_8).c0_;
                            local_19 = _e284;
                        } else {
                            local_19 = vec3<f32>(1f, 1f, 1f);
                        }
                        let _e285 = local_19;
                        local_18 = _e285;
                    } else {
                        local_18 = vec3<f32>(1f, 1f, 1f);
                    }
                    let _e286 = local_18;
                    tint = _e286;
                    let _e287 = f_4;
                    let _e288 = tint;
                    s_8.value = (_e287 * _e288);
                    let _e291 = pReflect;
                    s_8.pdf = _e291;
                } else {
                    let _e293 = (*l_8);
                    param_92 = _e293;
                    let _e294 = (*wo_9);
                    param_93 = _e294;
                    let _e296 = s_8.wi;
                    param_94 = _e296;
                    let _e297 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_92), (&param_93), (&param_94));
                    s_8.value = _e297;
                    let _e299 = (*l_8);
                    param_95 = _e299;
                    let _e300 = (*wo_9);
                    param_96 = _e300;
                    let _e302 = s_8.wi;
                    param_97 = _e302;
                    let _e303 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_95), (&param_96), (&param_97));
                    s_8.pdf = _e303;
                }
                let _e306 = s_8.pdf;
                s_8.valid = (_e306 > 0f);
                let _e309 = s_8;
                return _e309;
            }
            let _e310 = s_8;
            return _e310;
        }
        default: {
            let _e171 = (*wo_9)[2u];
            if (_e171 <= 0f) {
                let _e173 = s_8;
                return _e173;
            }
            let _e174 = (*u_4);
            param_98 = _e174.xy;
            let _e176 = mxc_sample_cosine_u0028_vf2_u003b((&param_98));
            s_8.wi = _e176;
            let _e178 = (*l_8);
            param_99 = _e178;
            let _e179 = (*wo_9);
            param_100 = _e179;
            let _e181 = s_8.wi;
            param_101 = _e181;
            let _e182 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_99), (&param_100), (&param_101));
            s_8.value = _e182;
            let _e184 = (*l_8);
            param_102 = _e184;
            let _e185 = (*wo_9);
            param_103 = _e185;
            let _e187 = s_8.wi;
            param_104 = _e187;
            let _e188 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_102), (&param_103), (&param_104));
            s_8.pdf = _e188;
            let _e191 = s_8.pdf;
            s_8.valid = (_e191 > 0f);
            let _e194 = s_8;
            return _e194;
        }
    }
}

fn mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b(c_7: ptr<function, MxcClosure>, wo_10: ptr<function, vec3<f32>>, u_5: ptr<function, vec3<f32>>) -> MxcSample {
    var s_9: MxcSample;
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
    var param_105: vec3<f32>;
    var param_106: vec3<f32>;
    var o_3: vec3<f32>;
    var param_107: mat3x3<f32>;
    var param_108: vec3<f32>;
    var ls: MxcLobeSample;
    var param_109: MxcLobe;
    var param_110: vec3<f32>;
    var param_111: vec3<f32>;
    var param_112: mat3x3<f32>;
    var param_113: vec3<f32>;
    var param_114: MxcLobe;
    var param_115: f32;

    s_9.valid = false;
    s_9.delta = false;
    s_9.evaluate = false;
    s_9.pdf = 0f;
    s_9.weight = vec3<f32>(0f, 0f, 0f);
    let _e152 = (*wo_10);
    s_9.wi = _e152;
    let _e155 = (*c_7).choiceTotal;
    total = _e155;
    let _e157 = (*c_7).count;
    let _e159 = total;
    if ((_e157 == 0i) || (_e159 <= 0f)) {
        let _e162 = s_9;
        return _e162;
    }
    let _e164 = (*u_5)[2u];
    let _e165 = total;
    x_2 = (_e164 * _e165);
    chosen = -1i;
    before = 0f;
    p_2 = 0f;
    lastBefore = 0f;
    last = -1i;
    k_2 = 0i;
    loop {
        let _e167 = k_2;
        let _e169 = (*c_7).count;
        if (_e167 < _e169) {
            let _e171 = k_2;
            let _e174 = (*c_7).choice[_e171];
            pk = _e174;
            let _e175 = pk;
            if (_e175 <= 0f) {
                continue;
            }
            let _e177 = x_2;
            let _e178 = before;
            let _e179 = pk;
            if (_e177 < (_e178 + _e179)) {
                let _e182 = k_2;
                chosen = _e182;
                let _e183 = pk;
                p_2 = _e183;
                break;
            }
            let _e184 = k_2;
            last = _e184;
            let _e185 = before;
            lastBefore = _e185;
            let _e186 = pk;
            let _e187 = before;
            before = (_e187 + _e186);
            continue;
        } else {
            break;
        }
        continuing {
            let _e189 = k_2;
            k_2 = (_e189 + 1i);
        }
    }
    let _e191 = chosen;
    if (_e191 < 0i) {
        let _e193 = last;
        chosen = max(_e193, 0i);
        let _e195 = chosen;
        let _e198 = (*c_7).choice[_e195];
        p_2 = _e198;
        let _e199 = lastBefore;
        before = _e199;
    }
    let _e200 = p_2;
    if (_e200 <= 0f) {
        let _e202 = s_9;
        return _e202;
    }
    let _e203 = x_2;
    let _e204 = before;
    let _e206 = p_2;
    uz = clamp(((_e203 - _e204) / _e206), 0f, 0.99999994f);
    let _e209 = chosen;
    let _e212 = (*c_7).lobes[_e209];
    l_9 = _e212;
    let _e214 = l_9.N;
    param_105 = _e214;
    let _e216 = l_9.T;
    param_106 = _e216;
    let _e217 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_105), (&param_106));
    frame_3 = _e217;
    let _e218 = frame_3;
    param_107 = _e218;
    let _e219 = (*wo_10);
    param_108 = _e219;
    let _e220 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_107), (&param_108));
    o_3 = _e220;
    let _e221 = (*u_5);
    let _e222 = _e221.xy;
    let _e223 = uz;
    let _e227 = l_9;
    param_109 = _e227;
    let _e228 = o_3;
    param_110 = _e228;
    param_111 = vec3<f32>(_e222.x, _e222.y, _e223);
    let _e229 = mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_109), (&param_110), (&param_111));
    ls = _e229;
    let _e231 = ls.valid;
    if !(_e231) {
        let _e233 = s_9;
        return _e233;
    }
    let _e234 = frame_3;
    param_112 = _e234;
    let _e236 = ls.wi;
    param_113 = _e236;
    let _e237 = mxc_to_world_u0028_mf33_u003b_vf3_u003b((&param_112), (&param_113));
    s_9.wi = _e237;
    let _e240 = ls.delta;
    if _e240 {
        s_9.delta = true;
        let _e243 = ls.pdf;
        let _e244 = p_2;
        let _e246 = total;
        s_9.pdf = ((_e243 * _e244) / _e246);
        let _e250 = l_9.weight;
        let _e251 = chosen;
        let _e254 = (*c_7).ms[_e251];
        let _e258 = ls.wi[2u];
        let _e260 = l_9;
        param_114 = _e260;
        param_115 = abs(_e258);
        let _e261 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_114), (&param_115));
        let _e264 = ls.value;
        let _e267 = s_9.pdf;
        s_9.weight = ((((_e250 * _e254) * _e261) * _e264) / vec3(_e267));
        let _e272 = s_9.pdf;
        s_9.valid = (_e272 > 0f);
        let _e275 = s_9;
        return _e275;
    }
    s_9.evaluate = true;
    s_9.valid = true;
    let _e278 = s_9;
    return _e278;
}

fn mxc_radical_inverse_u0028_u1_u003b_u1_u003b(i_5: ptr<function, u32>, base: ptr<function, u32>) -> f32 {
    var inv: f32;
    var f_5: f32;
    var r_3: f32;

    let _e123 = (*base);
    if (_e123 == 2u) {
        let _e125 = (*i_5);
        return (f32((reverseBits(_e125) >> bitcast<u32>(8i))) * 0.000000059604645f);
    }
    let _e131 = (*base);
    inv = (1f / f32(_e131));
    let _e134 = inv;
    f_5 = _e134;
    r_3 = 0f;
    loop {
        let _e135 = (*i_5);
        if (_e135 > 0u) {
            let _e137 = f_5;
            let _e138 = (*i_5);
            let _e139 = (*base);
            let _e143 = r_3;
            r_3 = (_e143 + (_e137 * f32((_e138 % _e139))));
            let _e145 = inv;
            let _e146 = f_5;
            f_5 = (_e146 * _e145);
            continue;
        } else {
            break;
        }
        continuing {
            let _e148 = (*base);
            let _e149 = (*i_5);
            (*i_5) = (_e149 / _e148);
        }
    }
    let _e151 = r_3;
    return min(_e151, 0.99999994f);
}

fn mxc_pcg_u0028_u1_u003b(v_5: ptr<function, u32>) -> u32 {
    var state: u32;
    var word: u32;

    let _e121 = (*v_5);
    state = ((_e121 * 747796405u) + 2891336453u);
    let _e124 = state;
    let _e125 = state;
    let _e131 = state;
    word = (((_e124 >> bitcast<u32>(((_e125 >> bitcast<u32>(28u)) + 4u))) ^ _e131) * 277803737u);
    let _e134 = word;
    let _e137 = word;
    return ((_e134 >> bitcast<u32>(22u)) ^ _e137);
}

fn mxc_uniform_u0028_u1_u003b(seed: ptr<function, u32>) -> f32 {
    var param_116: u32;

    let _e120 = (*seed);
    param_116 = _e120;
    let _e121 = mxc_pcg_u0028_u1_u003b((&param_116));
    (*seed) = _e121;
    let _e122 = (*seed);
    return (f32((_e122 >> bitcast<u32>(8i))) * 0.000000059604645f);
}

fn mxc_light_kinds_u0028_() -> i32 {
    return 7i;
}

fn mxc_light_count_u0028_() -> i32 {
    var local_20: i32;

    if false {
        local_20 = MXC_LIGHT_COUNT;
    } else {
        let _e121 = mxc_view.counts[0u];
        local_20 = _e121;
    }
    let _e122 = local_20;
    return min(_e122, 8i);
}

fn mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b(mu_2: ptr<function, f32>, x_3: ptr<function, f32>, firstRow: ptr<function, f32>) -> vec4<f32> {
    var t_3: vec2<f32>;

    let _e122 = (*mu_2);
    let _e125 = (*x_3);
    t_3 = ((vec2<f32>(sqrt(clamp(_e122, 0f, 1f)), clamp(_e125, 0f, 1f)) * 31f) + vec2(0.5f));
    let _e132 = t_3[0u];
    let _e134 = (*firstRow);
    let _e136 = t_3[1u];
    let _e140 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, vec2<f32>((_e132 / 32f), ((_e134 + _e136) / 2070f)), 0f);
    return _e140;
}

fn mxc_table_u0028_f1_u003b_f1_u003b(mu_3: ptr<function, f32>, x_4: ptr<function, f32>) -> vec4<f32> {
    var param_117: f32;
    var param_118: f32;
    var param_119: f32;

    let _e123 = (*mu_3);
    param_117 = _e123;
    let _e124 = (*x_4);
    param_118 = _e124;
    param_119 = 0f;
    let _e125 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_117), (&param_118), (&param_119));
    return _e125;
}

fn mxc_split_sum_u0028_f1_u003b_f1_u003b(mu_4: ptr<function, f32>, alpha_8: ptr<function, f32>) -> vec2<f32> {
    var param_120: f32;
    var param_121: f32;

    let _e122 = (*alpha_8);
    let _e125 = (*mu_4);
    param_120 = _e125;
    param_121 = sqrt(max(_e122, 0f));
    let _e126 = mxc_table_u0028_f1_u003b_f1_u003b((&param_120), (&param_121));
    return _e126.xy;
}

fn mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b(mu_5: ptr<function, f32>, alpha_9: ptr<function, f32>, e: ptr<function, f32>) -> vec4<f32> {
    var s_10: f32;
    var s0_: f32;
    var x_5: f32;
    var a_5: vec4<f32>;
    var param_122: f32;
    var param_123: f32;
    var param_124: f32;
    var b_2: vec4<f32>;
    var param_125: f32;
    var param_126: f32;
    var param_127: f32;

    let _e132 = (*e);
    s_10 = (sqrt(clamp((0.5f * (_e132 - 1f)), 0f, 1f)) * 31f);
    let _e138 = s_10;
    s0_ = min(floor(_e138), 30f);
    let _e141 = (*alpha_9);
    x_5 = sqrt(max(_e141, 0f));
    let _e144 = s0_;
    let _e147 = (*mu_5);
    param_122 = _e147;
    let _e148 = x_5;
    param_123 = _e148;
    param_124 = (32f * (1f + _e144));
    let _e149 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_122), (&param_123), (&param_124));
    a_5 = _e149;
    let _e150 = s0_;
    let _e153 = (*mu_5);
    param_125 = _e153;
    let _e154 = x_5;
    param_126 = _e154;
    param_127 = (32f * (2f + _e150));
    let _e155 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_125), (&param_126), (&param_127));
    b_2 = _e155;
    let _e156 = a_5;
    let _e157 = b_2;
    let _e158 = s_10;
    let _e159 = s0_;
    return mix(_e156, _e157, vec4((_e158 - _e159)));
}

fn mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b(mu_6: ptr<function, f32>, alpha_10: ptr<function, f32>, eta_1: ptr<function, f32>) -> f32 {
    var e_1: f32;
    var local_21: f32;
    var param_128: f32;
    var param_129: f32;
    var param_130: f32;

    let _e126 = (*eta_1);
    if (_e126 >= 1f) {
        let _e128 = (*eta_1);
        local_21 = _e128;
    } else {
        let _e129 = (*eta_1);
        local_21 = (1f / max(_e129, 0.001f));
    }
    let _e132 = local_21;
    e_1 = _e132;
    let _e133 = (*mu_6);
    param_128 = _e133;
    let _e134 = (*alpha_10);
    param_129 = _e134;
    let _e135 = e_1;
    param_130 = _e135;
    let _e136 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_128), (&param_129), (&param_130));
    return _e136.x;
}

fn mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_10: ptr<function, MxcLobe>, wo_11: ptr<function, vec3<f32>>, ms_1: ptr<function, vec3<f32>>) -> vec3<f32> {
    var mu_7: f32;
    var alpha_11: f32;
    var param_131: vec2<f32>;
    var e_2: vec3<f32>;
    var param_132: f32;
    var param_133: f32;
    var param_134: f32;
    var ab: vec2<f32>;
    var param_135: f32;
    var param_136: f32;
    var f0_: vec3<f32>;
    var param_137: MxcLobe;
    var param_138: f32;
    var param_139: bool;
    var f90_: vec3<f32>;
    var param_140: MxcLobe;
    var param_141: f32;
    var param_142: bool;
    var tint_1: vec3<f32>;
    var local_22: vec3<f32>;
    var param_143: vec2<f32>;
    var param_144: MxcLobe;
    var param_145: f32;
    var param_146: bool;
    var phi_2296_: bool;
    var phi_2303_: bool;
    var phi_2321_: bool;

    let _e146 = (*wo_11)[2u];
    mu_7 = clamp(_e146, 0f, 1f);
    let _e149 = (*l_10).kind;
    let _e150 = (_e149 == 1i);
    phi_2296_ = _e150;
    if !(_e150) {
        let _e153 = (*l_10).kind;
        phi_2296_ = (_e153 == 2i);
    }
    let _e156 = phi_2296_;
    phi_2303_ = _e156;
    if !(_e156) {
        let _e159 = (*l_10).kind;
        phi_2303_ = (_e159 == 3i);
    }
    let _e162 = phi_2303_;
    if _e162 {
        let _e165 = (*l_10).alpha[0u];
        let _e168 = (*l_10).alpha[1u];
        alpha_11 = sqrt((_e165 * _e168));
        let _e172 = (*l_10).kind;
        let _e173 = (_e172 == 1i);
        phi_2321_ = _e173;
        if _e173 {
            let _e175 = (*l_10).alpha;
            param_131 = _e175;
            let _e176 = mxc_is_delta_u0028_vf2_u003b((&param_131));
            phi_2321_ = !(_e176);
        }
        let _e179 = phi_2321_;
        if _e179 {
            let _e180 = mu_7;
            param_132 = _e180;
            let _e181 = alpha_11;
            param_133 = _e181;
            let _e183 = (*l_10).eta;
            param_134 = _e183;
            let _e184 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_132), (&param_133), (&param_134));
            e_2 = vec3(_e184);
            let _e186 = e_2;
            let _e188 = (*l_10).c0_;
            let _e190 = (*ms_1);
            return clamp(((_e186 * _e188) * _e190), vec3(0f), vec3(1f));
        }
        let _e195 = mu_7;
        param_135 = _e195;
        let _e196 = alpha_11;
        param_136 = _e196;
        let _e197 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_135), (&param_136));
        ab = _e197;
        let _e198 = (*l_10);
        param_137 = _e198;
        param_138 = 1f;
        param_139 = true;
        let _e199 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_137), (&param_138), (&param_139));
        f0_ = _e199;
        let _e200 = (*l_10);
        param_140 = _e200;
        param_141 = 0f;
        param_142 = true;
        let _e201 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_140), (&param_141), (&param_142));
        f90_ = _e201;
        let _e203 = (*l_10).kind;
        if (_e203 == 1i) {
            let _e206 = (*l_10).c0_;
            local_22 = _e206;
        } else {
            local_22 = vec3<f32>(1f, 1f, 1f);
        }
        let _e207 = local_22;
        tint_1 = _e207;
        let _e209 = (*l_10).alpha;
        param_143 = _e209;
        let _e210 = mxc_is_delta_u0028_vf2_u003b((&param_143));
        if _e210 {
            let _e211 = (*l_10);
            param_144 = _e211;
            let _e212 = mu_7;
            param_145 = _e212;
            param_146 = true;
            let _e213 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_144), (&param_145), (&param_146));
            let _e214 = tint_1;
            return (_e213 * _e214);
        }
        let _e216 = f0_;
        let _e218 = ab[0u];
        let _e220 = f90_;
        let _e222 = ab[1u];
        let _e225 = tint_1;
        let _e227 = (*ms_1);
        return clamp(((((_e216 * _e218) + (_e220 * _e222)) * _e225) * _e227), vec3(0f), vec3(1f));
    }
    let _e233 = (*l_10).kind;
    if (_e233 == 8i) {
        let _e236 = (*l_10).c0_;
        return _e236;
    }
    let _e238 = (*l_10).c0_;
    return _e238;
}

fn mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_11: ptr<function, MxcLobe>, woLocal: ptr<function, vec3<f32>>, ms_2: ptr<function, vec3<f32>>) -> f32 {
    var param_147: MxcLobe;
    var param_148: vec3<f32>;
    var param_149: vec3<f32>;
    var param_150: vec3<f32>;

    let _e126 = (*l_11).weight;
    if all((_e126 == vec3<f32>(0f, 0f, 0f))) {
        return 0f;
    }
    let _e130 = (*l_11).weight;
    let _e131 = (*l_11);
    param_147 = _e131;
    let _e132 = (*woLocal);
    param_148 = _e132;
    let _e133 = (*ms_2);
    param_149 = _e133;
    let _e134 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_147), (&param_148), (&param_149));
    param_150 = (_e130 * _e134);
    let _e136 = mxc_luminance_u0028_vf3_u003b((&param_150));
    return (max(_e136, 0f) + 0.0001f);
}

fn mxc_walk_texel_u0028_f1_u003b_f1_u003b(column: ptr<function, f32>, row: ptr<function, f32>) -> f32 {
    var t_4: vec2<f32>;

    let _e121 = (*column);
    let _e123 = (*row);
    t_4 = (vec2<f32>((_e121 + 0.5f), (_e123 + 0.5f)) / vec2<f32>(32f, 2070f));
    let _e127 = t_4;
    let _e128 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, _e127, 0f);
    return _e128.x;
}

fn mxc_walk_eta_index_u0028_f1_u003b(eta_2: ptr<function, f32>) -> f32 {
    var e_3: f32;

    let _e120 = (*eta_2);
    e_3 = max(_e120, 1f);
    let _e122 = e_3;
    let _e125 = e_3;
    return (clamp(((2f * (_e122 - 1f)) / (_e125 + 1f)), 0f, 1f) * 12f);
}

fn mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b(mu_8: ptr<function, f32>, alpha_12: ptr<function, f32>, eta_3: ptr<function, f32>) -> f32 {
    var fe: f32;
    var param_151: f32;
    var e0_: f32;
    var column_1: f32;
    var row_1: f32;
    var a_6: f32;
    var param_152: f32;
    var param_153: f32;
    var b_3: f32;
    var param_154: f32;
    var param_155: f32;

    let _e132 = (*eta_3);
    param_151 = _e132;
    let _e133 = mxc_walk_eta_index_u0028_f1_u003b((&param_151));
    fe = _e133;
    let _e134 = fe;
    e0_ = min(floor(_e134), 11f);
    let _e137 = (*mu_8);
    column_1 = (sqrt(clamp(_e137, 0f, 1f)) * 31f);
    let _e141 = (*alpha_12);
    row_1 = (1654f + (sqrt(clamp(_e141, 0f, 1f)) * 31f));
    let _e146 = row_1;
    let _e147 = e0_;
    let _e150 = column_1;
    param_152 = _e150;
    param_153 = (_e146 + (_e147 * 32f));
    let _e151 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_152), (&param_153));
    a_6 = _e151;
    let _e152 = row_1;
    let _e153 = e0_;
    let _e157 = column_1;
    param_154 = _e157;
    param_155 = (_e152 + ((_e153 + 1f) * 32f));
    let _e158 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_154), (&param_155));
    b_3 = _e158;
    let _e159 = a_6;
    let _e160 = b_3;
    let _e161 = fe;
    let _e162 = e0_;
    return mix(_e159, _e160, (_e161 - _e162));
}

fn mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b(mu_9: ptr<function, f32>, alpha_13: ptr<function, f32>, eta_4: ptr<function, f32>) -> f32 {
    var param_156: f32;
    var param_157: f32;
    var param_158: f32;
    var param_159: f32;
    var param_160: f32;
    var param_161: f32;

    let _e127 = (*eta_4);
    if (_e127 >= 1f) {
        let _e129 = (*mu_9);
        param_156 = _e129;
        let _e130 = (*alpha_13);
        param_157 = _e130;
        let _e131 = (*eta_4);
        param_158 = _e131;
        let _e132 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_156), (&param_157), (&param_158));
        return _e132.y;
    }
    let _e134 = (*eta_4);
    let _e137 = (*mu_9);
    param_159 = _e137;
    let _e138 = (*alpha_13);
    param_160 = _e138;
    param_161 = (1f / max(_e134, 0.001f));
    let _e139 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_159), (&param_160), (&param_161));
    return _e139.z;
}

fn mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_12: ptr<function, MxcLobe>, wo_12: ptr<function, vec3<f32>>) -> bool {
    var phi_2019_: bool;

    let _e121 = (*wo_12)[2u];
    let _e122 = (_e121 <= 0f);
    phi_2019_ = _e122;
    if !(_e122) {
        let _e125 = (*l_12).eta;
        phi_2019_ = (_e125 < 1f);
    }
    let _e128 = phi_2019_;
    if _e128 {
        return false;
    }
    return true;
}

fn mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_13: ptr<function, MxcLobe>) -> bool {
    let _e120 = (*l_13).eta;
    return (abs((_e120 - 1f)) < 0.0001f);
}

fn mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_14: ptr<function, MxcLobe>, wo_13: ptr<function, vec3<f32>>, ms_3: ptr<function, vec3<f32>>) -> f32 {
    var param_162: vec2<f32>;
    var param_163: MxcLobe;
    var param_164: MxcLobe;
    var param_165: vec3<f32>;
    var alpha_14: f32;
    var rss: f32;
    var param_166: f32;
    var param_167: f32;
    var param_168: f32;
    var tss: f32;
    var param_169: f32;
    var param_170: f32;
    var param_171: f32;
    var param_172: f32;
    var param_173: f32;
    var param_174: f32;
    var phi_2052_: bool;
    var phi_2058_: bool;
    var phi_2066_: bool;
    var phi_2074_: bool;

    let _e138 = (*l_14).kind;
    let _e139 = (_e138 != 1i);
    phi_2052_ = _e139;
    if !(_e139) {
        let _e142 = (*l_14).alpha;
        param_162 = _e142;
        let _e143 = mxc_is_delta_u0028_vf2_u003b((&param_162));
        phi_2052_ = _e143;
    }
    let _e145 = phi_2052_;
    phi_2058_ = _e145;
    if !(_e145) {
        let _e147 = (*l_14);
        param_163 = _e147;
        let _e148 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_163));
        phi_2058_ = _e148;
    }
    let _e150 = phi_2058_;
    phi_2066_ = _e150;
    if !(_e150) {
        let _e153 = (*l_14).mode;
        phi_2066_ = ((_e153 & 4i) != 0i);
    }
    let _e157 = phi_2066_;
    phi_2074_ = _e157;
    if !(_e157) {
        let _e159 = (*l_14);
        param_164 = _e159;
        let _e160 = (*wo_13);
        param_165 = _e160;
        let _e161 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_164), (&param_165));
        phi_2074_ = !(_e161);
    }
    let _e164 = phi_2074_;
    if _e164 {
        let _e166 = (*ms_3)[0u];
        return _e166;
    }
    let _e169 = (*l_14).alpha[0u];
    let _e172 = (*l_14).alpha[1u];
    alpha_14 = sqrt((_e169 * _e172));
    let _e176 = (*wo_13)[2u];
    param_166 = _e176;
    let _e177 = alpha_14;
    param_167 = _e177;
    let _e179 = (*l_14).eta;
    param_168 = _e179;
    let _e180 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_166), (&param_167), (&param_168));
    rss = _e180;
    let _e182 = (*wo_13)[2u];
    param_169 = _e182;
    let _e183 = alpha_14;
    param_170 = _e183;
    let _e185 = (*l_14).eta;
    param_171 = _e185;
    let _e186 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_169), (&param_170), (&param_171));
    let _e187 = rss;
    tss = (_e186 - _e187);
    let _e190 = (*wo_13)[2u];
    param_172 = _e190;
    let _e191 = alpha_14;
    param_173 = _e191;
    let _e193 = (*l_14).eta;
    param_174 = _e193;
    let _e194 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_172), (&param_173), (&param_174));
    let _e196 = tss;
    return clamp(((1f - _e194) / max(_e196, 0.05f)), 1f, 20f);
}

fn mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_15: ptr<function, MxcLobe>, wo_14: ptr<function, vec3<f32>>) -> vec3<f32> {
    var microfacet: bool;
    var param_175: vec2<f32>;
    var alpha_15: f32;
    var param_176: MxcLobe;
    var param_177: MxcLobe;
    var param_178: vec3<f32>;
    var rss_1: f32;
    var param_179: f32;
    var param_180: f32;
    var param_181: f32;
    var param_182: f32;
    var param_183: f32;
    var param_184: f32;
    var e_4: f32;
    var param_185: MxcLobe;
    var param_186: bool;
    var param_187: f32;
    var param_188: f32;
    var param_189: f32;
    var k_3: vec3<f32>;
    var ab_1: vec2<f32>;
    var param_190: f32;
    var param_191: f32;
    var e_5: f32;
    var param_192: MxcLobe;
    var param_193: f32;
    var param_194: bool;
    var phi_2150_: bool;
    var phi_2157_: bool;
    var phi_2166_: bool;
    var phi_2182_: bool;
    var phi_2194_: bool;

    let _e148 = (*l_15).kind;
    let _e149 = (_e148 == 1i);
    phi_2150_ = _e149;
    if !(_e149) {
        let _e152 = (*l_15).kind;
        phi_2150_ = (_e152 == 2i);
    }
    let _e155 = phi_2150_;
    phi_2157_ = _e155;
    if !(_e155) {
        let _e158 = (*l_15).kind;
        phi_2157_ = (_e158 == 3i);
    }
    let _e161 = phi_2157_;
    microfacet = _e161;
    let _e162 = microfacet;
    let _e163 = !(_e162);
    phi_2166_ = _e163;
    if !(_e163) {
        let _e166 = (*l_15).alpha;
        param_175 = _e166;
        let _e167 = mxc_is_delta_u0028_vf2_u003b((&param_175));
        phi_2166_ = _e167;
    }
    let _e169 = phi_2166_;
    if _e169 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e172 = (*l_15).alpha[0u];
    let _e175 = (*l_15).alpha[1u];
    alpha_15 = sqrt((_e172 * _e175));
    let _e179 = (*l_15).kind;
    let _e180 = (_e179 == 1i);
    phi_2182_ = _e180;
    if _e180 {
        let _e181 = (*l_15);
        param_176 = _e181;
        let _e182 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_176));
        phi_2182_ = _e182;
    }
    let _e184 = phi_2182_;
    if _e184 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e186 = (*l_15).kind;
    let _e187 = (_e186 == 1i);
    phi_2194_ = _e187;
    if _e187 {
        let _e189 = (*l_15).mode;
        phi_2194_ = ((_e189 & 4i) == 0i);
    }
    let _e193 = phi_2194_;
    if _e193 {
        let _e194 = (*l_15);
        param_177 = _e194;
        let _e195 = (*wo_14);
        param_178 = _e195;
        let _e196 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_177), (&param_178));
        if _e196 {
            let _e198 = (*wo_14)[2u];
            param_179 = _e198;
            let _e199 = alpha_15;
            param_180 = _e199;
            let _e201 = (*l_15).eta;
            param_181 = _e201;
            let _e202 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_179), (&param_180), (&param_181));
            rss_1 = _e202;
            let _e204 = (*wo_14)[2u];
            param_182 = _e204;
            let _e205 = alpha_15;
            param_183 = _e205;
            let _e207 = (*l_15).eta;
            param_184 = _e207;
            let _e208 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_182), (&param_183), (&param_184));
            let _e209 = rss_1;
            return vec3(clamp((_e208 / max(_e209, 0.0001f)), 1f, 20f));
        }
        let _e215 = (*wo_14)[2u];
        let _e218 = (*wo_14)[2u];
        let _e220 = (*l_15);
        param_185 = _e220;
        param_186 = (_e218 >= 0f);
        let _e221 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_185), (&param_186));
        param_187 = abs(_e215);
        let _e222 = alpha_15;
        param_188 = _e222;
        param_189 = _e221;
        let _e223 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_187), (&param_188), (&param_189));
        e_4 = _e223;
        let _e224 = e_4;
        k_3 = vec3((1f / max(_e224, 0.05f)));
        let _e228 = k_3;
        return _e228;
    }
    let _e230 = (*wo_14)[2u];
    param_190 = max(_e230, 0f);
    let _e232 = alpha_15;
    param_191 = _e232;
    let _e233 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_190), (&param_191));
    ab_1 = _e233;
    let _e235 = ab_1[0u];
    let _e237 = ab_1[1u];
    e_5 = (_e235 + _e237);
    let _e239 = (*l_15);
    param_192 = _e239;
    param_193 = 1f;
    param_194 = true;
    let _e240 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_192), (&param_193), (&param_194));
    let _e241 = e_5;
    let _e244 = e_5;
    return (vec3(1f) + ((_e240 * (1f - _e241)) / vec3(max(_e244, 0.05f))));
}

fn mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b(c_8: ptr<function, MxcClosure>, wo_15: ptr<function, vec3<f32>>) {
    var k_4: i32;
    var l_16: MxcLobe;
    var o_4: vec3<f32>;
    var param_195: vec3<f32>;
    var param_196: vec3<f32>;
    var param_197: mat3x3<f32>;
    var param_198: vec3<f32>;
    var param_199: MxcLobe;
    var param_200: vec3<f32>;
    var param_201: MxcLobe;
    var param_202: vec3<f32>;
    var param_203: vec3<f32>;
    var param_204: MxcLobe;
    var param_205: vec3<f32>;
    var param_206: vec3<f32>;

    (*c_8).choiceTotal = 0f;
    k_4 = 0i;
    loop {
        let _e136 = k_4;
        let _e138 = (*c_8).count;
        if (_e136 < _e138) {
            let _e140 = k_4;
            let _e143 = (*c_8).lobes[_e140];
            l_16 = _e143;
            let _e144 = k_4;
            (*c_8).ms[_e144] = vec3<f32>(1f, 1f, 1f);
            let _e147 = k_4;
            (*c_8).msT[_e147] = 1f;
            let _e150 = k_4;
            (*c_8).choice[_e150] = 0f;
            let _e154 = l_16.weight;
            if all((_e154 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e158 = l_16.N;
            param_195 = _e158;
            let _e160 = l_16.T;
            param_196 = _e160;
            let _e161 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_195), (&param_196));
            param_197 = _e161;
            let _e162 = (*wo_15);
            param_198 = _e162;
            let _e163 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_197), (&param_198));
            o_4 = _e163;
            let _e164 = k_4;
            let _e165 = l_16;
            param_199 = _e165;
            let _e166 = o_4;
            param_200 = _e166;
            let _e167 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_199), (&param_200));
            (*c_8).ms[_e164] = _e167;
            let _e170 = k_4;
            let _e171 = k_4;
            let _e172 = l_16;
            param_201 = _e172;
            let _e173 = o_4;
            param_202 = _e173;
            let _e176 = (*c_8).ms[_e171];
            param_203 = _e176;
            let _e177 = mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_201), (&param_202), (&param_203));
            (*c_8).msT[_e170] = _e177;
            let _e180 = k_4;
            let _e181 = k_4;
            let _e182 = l_16;
            param_204 = _e182;
            let _e183 = o_4;
            param_205 = _e183;
            let _e186 = (*c_8).ms[_e181];
            param_206 = _e186;
            let _e187 = mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_204), (&param_205), (&param_206));
            (*c_8).choice[_e180] = _e187;
            let _e190 = k_4;
            let _e193 = (*c_8).choice[_e190];
            let _e195 = (*c_8).choiceTotal;
            (*c_8).choiceTotal = (_e195 + _e193);
            continue;
        } else {
            break;
        }
        continuing {
            let _e198 = k_4;
            k_4 = (_e198 + 1i);
        }
    }
    return;
}

fn mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_17: ptr<function, MxcLobe>, wo_16: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_207: MxcLobe;
    var param_208: vec3<f32>;
    var param_209: MxcLobe;
    var param_210: vec3<f32>;
    var param_211: vec3<f32>;

    let _e125 = (*l_17);
    param_207 = _e125;
    let _e126 = (*wo_16);
    param_208 = _e126;
    let _e127 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_207), (&param_208));
    let _e128 = (*l_17);
    param_209 = _e128;
    let _e129 = (*wo_16);
    param_210 = _e129;
    param_211 = _e127;
    let _e130 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_209), (&param_210), (&param_211));
    return _e130;
}

fn mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_18: ptr<function, MxcLobe>, wo_17: ptr<function, vec3<f32>>) -> vec3<f32> {
    var white: MxcLobe;
    var param_212: MxcLobe;
    var param_213: vec3<f32>;
    var param_214: MxcLobe;
    var param_215: vec3<f32>;
    var phi_2423_: bool;

    let _e126 = (*l_18).kind;
    let _e127 = (_e126 == 9i);
    phi_2423_ = _e127;
    if !(_e127) {
        let _e130 = (*l_18).kind;
        phi_2423_ = (_e130 == 10i);
    }
    let _e133 = phi_2423_;
    if _e133 {
        let _e134 = (*l_18);
        white = _e134;
        white.c0_ = vec3<f32>(1f, 1f, 1f);
        let _e136 = white;
        param_212 = _e136;
        let _e137 = (*wo_17);
        param_213 = _e137;
        let _e138 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_212), (&param_213));
        return _e138;
    }
    let _e139 = (*l_18);
    param_214 = _e139;
    let _e140 = (*wo_17);
    param_215 = _e140;
    let _e141 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_214), (&param_215));
    return _e141;
}

fn mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b(g_1: ptr<function, MxcGeometry>, wo_18: ptr<function, vec3<f32>>, c_9: ptr<function, MxcClosure>) {
    var v5_: vec3<f32>;
    var v6_: vec3<f32>;
    var lobe0_: MxcLobe;
    var e1_: vec3<f32>;
    var param_216: vec3<f32>;
    var param_217: vec3<f32>;
    var param_218: mat3x3<f32>;
    var param_219: vec3<f32>;
    var param_220: MxcLobe;
    var param_221: vec3<f32>;
    var w2_: vec3<f32>;
    var lobe3_: MxcLobe;
    var param_222: MxcClosure;
    var param_223: vec3<f32>;

    let _e136 = (*g_1).N;
    v5_ = _e136;
    let _e138 = (*g_1).T;
    v6_ = _e138;
    (*c_9).emission = vec3<f32>(0f, 0f, 0f);
    (*c_9).transparency = vec3<f32>(0f, 0f, 0f);
    lobe0_.kind = 1i;
    lobe0_.mode = 1i;
    let _e143 = v5_;
    lobe0_.N = _e143;
    let _e145 = v6_;
    lobe0_.T = _e145;
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
    let _e158 = lobe0_.N;
    param_216 = _e158;
    let _e160 = lobe0_.T;
    param_217 = _e160;
    let _e161 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_216), (&param_217));
    param_218 = _e161;
    let _e162 = (*wo_18);
    param_219 = _e162;
    let _e163 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_218), (&param_219));
    let _e164 = lobe0_;
    param_220 = _e164;
    param_221 = _e163;
    let _e165 = mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_220), (&param_221));
    e1_ = _e165;
    let _e166 = e1_;
    w2_ = (vec3<f32>(1f, 1f, 1f) - _e166);
    lobe3_.kind = 5i;
    lobe3_.mode = 1i;
    let _e170 = v5_;
    lobe3_.N = _e170;
    let _e173 = (*g_1).T;
    lobe3_.T = _e173;
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
    let _e186 = lobe0_;
    (*c_9).lobes[0i] = _e186;
    let _e189 = w2_;
    lobe3_.weight = _e189;
    let _e191 = lobe3_;
    (*c_9).lobes[1i] = _e191;
    (*c_9).count = 2i;
    let _e195 = (*c_9);
    param_222 = _e195;
    let _e196 = (*wo_18);
    param_223 = _e196;
    mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b((&param_222), (&param_223));
    let _e197 = param_222;
    (*c_9) = _e197;
    return;
}

fn mxc_closure_seed_u0028_u1_u003b(seed_1: ptr<function, u32>) {
    return;
}

fn mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b(v_6: ptr<function, vec3<f32>>, fallback: ptr<function, vec3<f32>>) -> vec3<f32> {
    var l2_1: f32;
    var local_23: vec3<f32>;

    let _e122 = (*v_6);
    let _e123 = (*v_6);
    l2_1 = dot(_e122, _e123);
    let _e125 = l2_1;
    if (_e125 > 0.00000000000000000001f) {
        let _e127 = (*v_6);
        let _e128 = l2_1;
        local_23 = (_e127 * inverseSqrt(_e128));
    } else {
        let _e131 = (*fallback);
        local_23 = _e131;
    }
    let _e132 = local_23;
    return _e132;
}

fn main_1() {
    var g_2: MxcGeometry;
    var N_1: vec3<f32>;
    var param_224: vec3<f32>;
    var param_225: vec3<f32>;
    var wo_19: vec3<f32>;
    var param_226: vec3<f32>;
    var param_227: vec3<f32>;
    var facing: f32;
    var handedness: f32;
    var frame_4: mat3x3<f32>;
    var param_228: vec3<f32>;
    var param_229: vec3<f32>;
    var param_230: vec3<f32>;
    var param_231: vec3<f32>;
    var objectFrame: mat3x3<f32>;
    var param_232: vec3<f32>;
    var param_233: vec3<f32>;
    var param_234: u32;
    var param_235: u32;
    var param_236: u32;
    var param_237: u32;
    var c_10: MxcClosure;
    var param_238: MxcGeometry;
    var param_239: vec3<f32>;
    var param_240: MxcClosure;
    var radiance: vec3<f32>;
    var lights: i32;
    var kinds: i32;
    var image: bool;
    var n_1: i32;
    var local_24: i32;
    var seed_2: u32;
    var param_241: u32;
    var param_242: u32;
    var param_243: u32;
    var pixel: u32;
    var param_244: u32;
    var param_245: u32;
    var shift: vec4<f32>;
    var param_246: u32;
    var param_247: u32;
    var param_248: u32;
    var param_249: u32;
    var sum: vec3<f32>;
    var b_4: i32;
    var batchLights: i32;
    var batchSamples: i32;
    var local_25: i32;
    var index: u32;
    var choice: vec4<f32>;
    var param_250: u32;
    var param_251: u32;
    var param_252: u32;
    var param_253: u32;
    var param_254: u32;
    var param_255: u32;
    var param_256: u32;
    var param_257: u32;
    var smp: MxcSample;
    var param_258: MxcClosure;
    var param_259: vec3<f32>;
    var param_260: vec3<f32>;
    var above_4: bool;
    var seen: vec3<f32>;
    var local_26: vec3<f32>;
    var local_27: vec3<f32>;
    var param_261: vec3<f32>;
    var param_262: vec3<f32>;
    var param_263: vec3<f32>;
    var w_1: f32;
    var local_28: f32;
    var param_264: vec3<f32>;
    var param_265: f32;
    var param_266: vec3<f32>;
    var param_267: f32;
    var param_268: f32;
    var m_5: vec3<f32>;
    var lightPdf: f32;
    var imageWi: vec3<f32>;
    var imageSeen: vec3<f32>;
    var v_7: vec4<f32>;
    var param_269: u32;
    var param_270: u32;
    var param_271: u32;
    var param_272: vec4<f32>;
    var param_273: f32;
    var param_274: vec3<f32>;
    var param_275: f32;
    var param_276: vec3<f32>;
    var j_2: i32;
    var wi_7: vec3<f32>;
    var incoming: vec3<f32>;
    var use_: bool;
    var strategy: i32;
    var local_29: i32;
    var light: vec4<f32>;
    var directional: bool;
    var param_277: vec3<f32>;
    var param_278: vec3<f32>;
    var d_8: vec3<f32>;
    var d2_: f32;
    var spot: vec4<f32>;
    var f_6: vec3<f32>;
    var pdf_2: f32;
    var param_279: MxcClosure;
    var param_280: vec3<f32>;
    var param_281: vec3<f32>;
    var param_282: bool;
    var param_283: f32;
    var w_2: f32;
    var local_30: f32;
    var param_284: vec3<f32>;
    var param_285: f32;
    var param_286: vec3<f32>;
    var param_287: f32;
    var param_288: f32;
    var w_3: f32;
    var param_289: vec3<f32>;
    var param_290: f32;
    var param_291: f32;
    var coverage: f32;
    var param_292: vec3<f32>;
    var phi_621_: bool;
    var phi_632_: bool;
    var phi_694_: bool;
    var phi_751_: bool;
    var phi_752_: bool;
    var phi_785_: bool;
    var phi_827_: bool;

    let _e240 = vPosition_1;
    g_2.P = _e240;
    let _e242 = vObjectPosition_1;
    g_2.Pobj = _e242;
    let _e244 = vNormal_1;
    param_224 = _e244;
    param_225 = vec3<f32>(0f, 0f, 1f);
    let _e245 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_224), (&param_225));
    N_1 = _e245;
    let _e246 = gl_FrontFacing_1;
    if !(_e246) {
        let _e248 = N_1;
        N_1 = -(_e248);
    }
    let _e251 = mxc_view.eye;
    let _e253 = vPosition_1;
    param_226 = (_e251.xyz - _e253);
    let _e255 = N_1;
    param_227 = _e255;
    let _e256 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_226), (&param_227));
    wo_19 = _e256;
    let _e257 = wo_19;
    let _e258 = N_1;
    facing = dot(_e257, _e258);
    let _e260 = facing;
    if (_e260 < 0.01f) {
        let _e262 = N_1;
        let _e263 = facing;
        let _e265 = wo_19;
        N_1 = normalize((_e262 + (_e265 * (0.01f - _e263))));
    }
    let _e270 = vTangent_1[3u];
    handedness = select(1f, -1f, (_e270 < 0f));
    let _e273 = N_1;
    param_228 = _e273;
    let _e274 = vTangent_1;
    param_229 = _e274.xyz;
    let _e276 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_228), (&param_229));
    frame_4 = _e276;
    let _e277 = N_1;
    g_2.N = _e277;
    let _e280 = frame_4[0];
    g_2.T = _e280;
    let _e283 = frame_4[1];
    let _e284 = handedness;
    g_2.B = (_e283 * _e284);
    let _e287 = vObjectNormal_1;
    param_230 = _e287;
    param_231 = vec3<f32>(0f, 0f, 1f);
    let _e288 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_230), (&param_231));
    g_2.Nobj = _e288;
    let _e291 = g_2.Nobj;
    param_232 = _e291;
    let _e292 = vObjectTangent_1;
    param_233 = _e292;
    let _e293 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_232), (&param_233));
    objectFrame = _e293;
    let _e295 = objectFrame[0];
    g_2.Tobj = _e295;
    let _e298 = objectFrame[1];
    let _e299 = handedness;
    g_2.Bobj = (_e298 * _e299);
    let _e302 = vUv_1;
    g_2.uv = _e302;
    g_2.color = vec4<f32>(1f, 1f, 1f, 1f);
    let _e306 = mxc_view.objectToWorld;
    g_2.objectToWorld = _e306;
    let _e309 = mxc_params.frame;
    g_2.frame = _e309;
    let _e312 = mxc_params.time;
    g_2.time = _e312;
    let _e315 = gl_FragCoord_1[0u];
    let _e318 = gl_FragCoord_1[1u];
    let _e322 = mxc_view.counts[2u];
    param_234 = (bitcast<u32>(_e322) + 7u);
    let _e325 = mxc_pcg_u0028_u1_u003b((&param_234));
    param_235 = (u32(_e318) + _e325);
    let _e327 = mxc_pcg_u0028_u1_u003b((&param_235));
    param_236 = (u32(_e315) ^ _e327);
    let _e329 = mxc_pcg_u0028_u1_u003b((&param_236));
    param_237 = _e329;
    mxc_closure_seed_u0028_u1_u003b((&param_237));
    let _e330 = g_2;
    param_238 = _e330;
    let _e331 = wo_19;
    param_239 = _e331;
    mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b((&param_238), (&param_239), (&param_240));
    let _e332 = param_240;
    c_10 = _e332;
    let _e334 = c_10.emission;
    let _e337 = mxc_view.environment[1u];
    radiance = (_e334 * _e337);
    let _e339 = mxc_light_count_u0028_();
    lights = _e339;
    let _e340 = mxc_light_kinds_u0028_();
    kinds = _e340;
    let _e341 = mxc_environment_code_u0028_();
    image = (_e341 == 3i);
    let _e343 = mxc_environment_code_u0028_();
    if (_e343 != 0i) {
        let _e347 = mxc_view.counts[3u];
        local_24 = max(_e347, 1i);
    } else {
        local_24 = 0i;
    }
    let _e349 = local_24;
    n_1 = _e349;
    let _e351 = gl_FragCoord_1[0u];
    let _e354 = gl_FragCoord_1[1u];
    let _e358 = mxc_view.counts[2u];
    param_241 = bitcast<u32>(_e358);
    let _e360 = mxc_pcg_u0028_u1_u003b((&param_241));
    param_242 = (u32(_e354) + _e360);
    let _e362 = mxc_pcg_u0028_u1_u003b((&param_242));
    param_243 = (u32(_e351) + _e362);
    let _e364 = mxc_pcg_u0028_u1_u003b((&param_243));
    seed_2 = _e364;
    let _e366 = gl_FragCoord_1[0u];
    let _e369 = gl_FragCoord_1[1u];
    param_244 = (u32(_e369) + 2654435769u);
    let _e372 = mxc_pcg_u0028_u1_u003b((&param_244));
    param_245 = (u32(_e366) ^ _e372);
    let _e374 = mxc_pcg_u0028_u1_u003b((&param_245));
    pixel = _e374;
    let _e375 = pixel;
    param_246 = _e375;
    let _e376 = mxc_uniform_u0028_u1_u003b((&param_246));
    let _e377 = param_246;
    pixel = _e377;
    let _e378 = pixel;
    param_247 = _e378;
    let _e379 = mxc_uniform_u0028_u1_u003b((&param_247));
    let _e380 = param_247;
    pixel = _e380;
    let _e381 = pixel;
    param_248 = _e381;
    let _e382 = mxc_uniform_u0028_u1_u003b((&param_248));
    let _e383 = param_248;
    pixel = _e383;
    let _e384 = pixel;
    param_249 = _e384;
    let _e385 = mxc_uniform_u0028_u1_u003b((&param_249));
    let _e386 = param_249;
    pixel = _e386;
    shift = vec4<f32>(_e376, _e379, _e382, _e385);
    sum = vec3<f32>(0f, 0f, 0f);
    b_4 = 0i;
    loop {
        let _e388 = b_4;
        let _e389 = n_1;
        let _e390 = lights;
        if (_e388 < max(_e389, select(0i, 1i, (_e390 > 0i)))) {
            let _e395 = b_4;
            let _e397 = lights;
            batchLights = select(0i, _e397, (_e395 == 0i));
            let _e399 = b_4;
            let _e400 = n_1;
            if (_e399 < _e400) {
                let _e402 = image;
                local_25 = (1i + select(0i, 1i, _e402));
            } else {
                local_25 = 0i;
            }
            let _e405 = local_25;
            batchSamples = _e405;
            let _e408 = mxc_view.counts[2u];
            let _e410 = n_1;
            let _e414 = b_4;
            index = ((bitcast<u32>(_e408) * bitcast<u32>(max(_e410, 1i))) + bitcast<u32>(_e414));
            let _e417 = index;
            param_250 = _e417;
            param_251 = 2u;
            let _e418 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_250), (&param_251));
            let _e419 = index;
            param_252 = _e419;
            param_253 = 3u;
            let _e420 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_252), (&param_253));
            let _e421 = index;
            param_254 = _e421;
            param_255 = 5u;
            let _e422 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_254), (&param_255));
            let _e423 = index;
            param_256 = _e423;
            param_257 = 7u;
            let _e424 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_256), (&param_257));
            let _e426 = shift;
            choice = fract((vec4<f32>(_e418, _e420, _e422, _e424) + _e426));
            smp.valid = false;
            smp.evaluate = false;
            smp.delta = false;
            smp.pdf = 0f;
            smp.weight = vec3<f32>(0f, 0f, 0f);
            let _e434 = N_1;
            smp.wi = _e434;
            let _e436 = n_1;
            if (_e436 > 0i) {
                let _e439 = choice[2u];
                let _e441 = choice[3u];
                let _e443 = choice[0u];
                let _e445 = c_10;
                param_258 = _e445;
                let _e446 = wo_19;
                param_259 = _e446;
                param_260 = vec3<f32>(_e439, _e441, _e443);
                let _e447 = mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b((&param_258), (&param_259), (&param_260));
                smp = _e447;
            }
            let _e449 = smp.wi;
            let _e450 = N_1;
            above_4 = (dot(_e449, _e450) > 0f);
            let _e454 = smp.valid;
            if _e454 {
                let _e455 = above_4;
                if _e455 {
                    let _e457 = smp.wi;
                    local_27 = _e457;
                } else {
                    let _e458 = wo_19;
                    param_261 = -(_e458);
                    let _e461 = smp.wi;
                    param_262 = _e461;
                    let _e462 = mxc_exit_direction_u0028_vf3_u003b_vf3_u003b((&param_261), (&param_262));
                    local_27 = _e462;
                }
                let _e463 = local_27;
                param_263 = _e463;
                let _e464 = mxc_environment_u0028_vf3_u003b((&param_263));
                local_26 = _e464;
            } else {
                local_26 = vec3<f32>(0f, 0f, 0f);
            }
            let _e465 = local_26;
            seen = _e465;
            let _e466 = b_4;
            let _e467 = n_1;
            let _e470 = smp.valid;
            let _e471 = ((_e466 < _e467) && _e470);
            phi_621_ = _e471;
            if _e471 {
                let _e473 = smp.evaluate;
                phi_621_ = !(_e473);
            }
            let _e476 = phi_621_;
            if _e476 {
                let _e477 = image;
                let _e478 = above_4;
                let _e479 = (_e477 && _e478);
                phi_632_ = _e479;
                if _e479 {
                    let _e481 = smp.delta;
                    phi_632_ = !(_e481);
                }
                let _e484 = phi_632_;
                if _e484 {
                    let _e486 = smp.wi;
                    param_264 = _e486;
                    let _e489 = mxc_view.environment[2u];
                    param_265 = _e489;
                    let _e490 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_264), (&param_265));
                    param_266 = _e490;
                    let _e491 = mxc_env_pdf_u0028_vf3_u003b((&param_266));
                    let _e493 = smp.pdf;
                    param_267 = _e493;
                    param_268 = _e491;
                    let _e494 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_267), (&param_268));
                    local_28 = _e494;
                } else {
                    local_28 = 1f;
                }
                let _e495 = local_28;
                w_1 = _e495;
                let _e496 = w_1;
                let _e498 = smp.weight;
                let _e500 = seen;
                let _e502 = sum;
                sum = (_e502 + ((_e498 * _e496) * _e500));
            }
            m_5 = vec3<f32>(0f, 0f, 0f);
            lightPdf = 0f;
            let _e504 = N_1;
            imageWi = _e504;
            imageSeen = vec3<f32>(0f, 0f, 0f);
            let _e505 = image;
            let _e506 = b_4;
            let _e507 = n_1;
            if (_e505 && (_e506 < _e507)) {
                let _e511 = choice[1u];
                let _e512 = seed_2;
                param_269 = _e512;
                let _e513 = mxc_uniform_u0028_u1_u003b((&param_269));
                let _e514 = param_269;
                seed_2 = _e514;
                let _e515 = seed_2;
                param_270 = _e515;
                let _e516 = mxc_uniform_u0028_u1_u003b((&param_270));
                let _e517 = param_270;
                seed_2 = _e517;
                let _e518 = seed_2;
                param_271 = _e518;
                let _e519 = mxc_uniform_u0028_u1_u003b((&param_271));
                let _e520 = param_271;
                seed_2 = _e520;
                v_7 = vec4<f32>(_e511, _e513, _e516, _e519);
                let _e522 = v_7;
                param_272 = _e522;
                let _e523 = mxc_env_sample_u0028_vf4_u003b_f1_u003b((&param_272), (&param_273));
                let _e524 = param_273;
                lightPdf = _e524;
                m_5 = _e523;
                let _e525 = m_5;
                param_274 = _e525;
                let _e528 = mxc_view.environment[2u];
                param_275 = _e528;
                let _e529 = mxc_env_to_world_u0028_vf3_u003b_f1_u003b((&param_274), (&param_275));
                imageWi = _e529;
                let _e530 = lightPdf;
                let _e531 = (_e530 > 0f);
                phi_694_ = _e531;
                if _e531 {
                    let _e532 = imageWi;
                    let _e533 = N_1;
                    phi_694_ = (dot(_e532, _e533) > 0f);
                }
                let _e537 = phi_694_;
                if _e537 {
                    let _e538 = imageWi;
                    param_276 = _e538;
                    let _e539 = mxc_environment_u0028_vf3_u003b((&param_276));
                    imageSeen = _e539;
                }
            }
            j_2 = 0i;
            loop {
                let _e540 = j_2;
                let _e541 = batchLights;
                let _e542 = batchSamples;
                if (_e540 < (_e541 + _e542)) {
                    let _e545 = N_1;
                    wi_7 = _e545;
                    incoming = vec3<f32>(0f, 0f, 0f);
                    use_ = true;
                    let _e546 = n_1;
                    let _e548 = j_2;
                    let _e549 = batchLights;
                    if ((_e546 == 0i) || (_e548 < _e549)) {
                        local_29 = 0i;
                    } else {
                        let _e552 = j_2;
                        let _e553 = batchLights;
                        local_29 = select(2i, 1i, (_e552 == ((_e553 + 1i) - 1i)));
                    }
                    let _e558 = local_29;
                    strategy = _e558;
                    let _e559 = strategy;
                    if (_e559 == 0i) {
                        let _e561 = j_2;
                        let _e564 = mxc_view.lightVector[_e561];
                        light = _e564;
                        let _e565 = j_2;
                        let _e568 = mxc_view.lightRadiance[_e565];
                        incoming = _e568.xyz;
                        let _e570 = kinds;
                        let _e571 = (_e570 == 1i);
                        phi_752_ = _e571;
                        if !(_e571) {
                            let _e573 = kinds;
                            let _e575 = ((_e573 & 1i) != 0i);
                            phi_751_ = _e575;
                            if _e575 {
                                let _e577 = light[3u];
                                phi_751_ = (_e577 == 0f);
                            }
                            let _e580 = phi_751_;
                            phi_752_ = _e580;
                        }
                        let _e582 = phi_752_;
                        directional = _e582;
                        let _e583 = directional;
                        if _e583 {
                            let _e584 = light;
                            param_277 = _e584.xyz;
                            let _e586 = N_1;
                            param_278 = _e586;
                            let _e587 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_277), (&param_278));
                            wi_7 = _e587;
                        } else {
                            let _e588 = light;
                            let _e590 = vPosition_1;
                            d_8 = (_e588.xyz - _e590);
                            let _e592 = d_8;
                            let _e593 = d_8;
                            d2_ = max(dot(_e592, _e593), 0.00000001f);
                            let _e596 = d_8;
                            let _e597 = d2_;
                            wi_7 = (_e596 * inverseSqrt(_e597));
                            let _e600 = d2_;
                            let _e601 = incoming;
                            incoming = (_e601 / vec3(_e600));
                            let _e604 = kinds;
                            let _e606 = ((_e604 & 4i) != 0i);
                            phi_785_ = _e606;
                            if _e606 {
                                let _e608 = light[3u];
                                phi_785_ = (_e608 == 2f);
                            }
                            let _e611 = phi_785_;
                            if _e611 {
                                let _e612 = j_2;
                                let _e615 = mxc_view.lightSpot[_e612];
                                spot = _e615;
                                let _e617 = spot[3u];
                                let _e618 = j_2;
                                let _e622 = mxc_view.lightRadiance[_e618][3u];
                                let _e623 = wi_7;
                                let _e625 = spot;
                                let _e629 = incoming;
                                incoming = (_e629 * smoothstep(_e617, _e622, dot(-(_e623), _e625.xyz)));
                            }
                        }
                    } else {
                        let _e631 = strategy;
                        if (_e631 == 1i) {
                            let _e634 = smp.wi;
                            wi_7 = _e634;
                            let _e635 = seen;
                            incoming = _e635;
                            let _e637 = smp.valid;
                            let _e639 = smp.evaluate;
                            use_ = (_e637 && _e639);
                        } else {
                            let _e641 = imageWi;
                            wi_7 = _e641;
                            let _e642 = imageSeen;
                            incoming = _e642;
                            let _e643 = lightPdf;
                            let _e644 = (_e643 > 0f);
                            phi_827_ = _e644;
                            if _e644 {
                                let _e645 = imageWi;
                                let _e646 = N_1;
                                phi_827_ = (dot(_e645, _e646) > 0f);
                            }
                            let _e650 = phi_827_;
                            use_ = _e650;
                        }
                    }
                    let _e651 = strategy;
                    let _e653 = c_10;
                    param_279 = _e653;
                    let _e654 = wo_19;
                    param_280 = _e654;
                    let _e655 = wi_7;
                    param_281 = _e655;
                    param_282 = (_e651 != 0i);
                    let _e656 = mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b((&param_279), (&param_280), (&param_281), (&param_282), (&param_283));
                    let _e657 = param_283;
                    pdf_2 = _e657;
                    f_6 = _e656;
                    let _e658 = strategy;
                    if (_e658 == 0i) {
                        let _e660 = f_6;
                        let _e661 = incoming;
                        let _e663 = radiance;
                        radiance = (_e663 + (_e660 * _e661));
                    } else {
                        let _e665 = strategy;
                        if (_e665 == 1i) {
                            let _e667 = use_;
                            let _e668 = pdf_2;
                            if (_e667 && (_e668 > 0f)) {
                                let _e671 = image;
                                let _e672 = above_4;
                                if (_e671 && _e672) {
                                    let _e674 = wi_7;
                                    param_284 = _e674;
                                    let _e677 = mxc_view.environment[2u];
                                    param_285 = _e677;
                                    let _e678 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_284), (&param_285));
                                    param_286 = _e678;
                                    let _e679 = mxc_env_pdf_u0028_vf3_u003b((&param_286));
                                    let _e680 = pdf_2;
                                    param_287 = _e680;
                                    param_288 = _e679;
                                    let _e681 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_287), (&param_288));
                                    local_30 = _e681;
                                } else {
                                    local_30 = 1f;
                                }
                                let _e682 = local_30;
                                w_2 = _e682;
                                let _e683 = w_2;
                                let _e684 = f_6;
                                let _e686 = pdf_2;
                                let _e689 = incoming;
                                let _e691 = sum;
                                sum = (_e691 + (((_e684 * _e683) / vec3(_e686)) * _e689));
                            }
                        } else {
                            let _e693 = use_;
                            if _e693 {
                                let _e694 = m_5;
                                param_289 = _e694;
                                let _e695 = mxc_env_pdf_u0028_vf3_u003b((&param_289));
                                param_290 = _e695;
                                let _e696 = pdf_2;
                                param_291 = _e696;
                                let _e697 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_290), (&param_291));
                                w_3 = _e697;
                                let _e698 = w_3;
                                let _e699 = f_6;
                                let _e701 = incoming;
                                let _e703 = lightPdf;
                                let _e706 = sum;
                                sum = (_e706 + (((_e699 * _e698) * _e701) / vec3(_e703)));
                            }
                        }
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e708 = j_2;
                    j_2 = (_e708 + 1i);
                }
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e710 = b_4;
            b_4 = (_e710 + 1i);
        }
    }
    let _e712 = sum;
    let _e713 = n_1;
    let _e718 = radiance;
    radiance = (_e718 + (_e712 / vec3(f32(max(_e713, 1i)))));
    let _e721 = c_10.transparency;
    param_292 = _e721;
    let _e722 = mxc_luminance_u0028_vf3_u003b((&param_292));
    coverage = (1f - clamp(_e722, 0f, 1f));
    let _e725 = radiance;
    let _e726 = coverage;
    outColor = vec4<f32>(_e725.x, _e725.y, _e725.z, _e726);
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
