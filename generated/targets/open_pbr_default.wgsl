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
var<private> vTangent_1: vec4<f32>;
var<private> vObjectNormal_1: vec3<f32>;
var<private> vObjectTangent_1: vec3<f32>;
var<private> vUv_1: vec2<f32>;
@group(0) @binding(1) 
var<uniform> mxc_view: MxcView;
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
    let _e113 = (*c);
    return dot(_e113, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l: ptr<function, MxcLobe>) -> bool {
    return false;
}

fn mxc_mean_u0028_vf3_u003b(c_1: ptr<function, vec3<f32>>) -> f32 {
    let _e114 = (*c_1)[0u];
    let _e116 = (*c_1)[1u];
    let _e119 = (*c_1)[2u];
    return (((_e114 + _e116) + _e119) * 0.33333334f);
}

fn mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b(cosi: ptr<function, f32>, eta: ptr<function, f32>) -> f32 {
    var sin2t: f32;
    var cost: f32;
    var rs: f32;
    var rp: f32;

    let _e118 = (*eta);
    if (abs((_e118 - 1f)) < 0.000001f) {
        return 0f;
    }
    let _e122 = (*cosi);
    let _e123 = (*cosi);
    let _e126 = (*eta);
    let _e127 = (*eta);
    sin2t = ((1f - (_e122 * _e123)) / (_e126 * _e127));
    let _e130 = sin2t;
    if (_e130 >= 1f) {
        return 1f;
    }
    let _e132 = sin2t;
    cost = sqrt((1f - _e132));
    let _e135 = (*cosi);
    let _e136 = (*eta);
    let _e137 = cost;
    let _e140 = (*cosi);
    let _e141 = (*eta);
    let _e142 = cost;
    rs = ((_e135 - (_e136 * _e137)) / (_e140 + (_e141 * _e142)));
    let _e146 = (*eta);
    let _e147 = (*cosi);
    let _e149 = cost;
    let _e151 = (*eta);
    let _e152 = (*cosi);
    let _e154 = cost;
    rp = (((_e146 * _e147) - _e149) / ((_e151 * _e152) + _e154));
    let _e157 = rs;
    let _e158 = rs;
    let _e160 = rp;
    let _e161 = rp;
    return (0.5f * ((_e157 * _e158) + (_e160 * _e161)));
}

fn mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_1: ptr<function, MxcLobe>, above: ptr<function, bool>) -> f32 {
    var local: f32;

    let _e115 = (*above);
    if _e115 {
        let _e117 = (*l_1).eta;
        local = _e117;
    } else {
        let _e119 = (*l_1).eta;
        local = (1f / _e119);
    }
    let _e121 = local;
    return _e121;
}

fn mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b(l_2: ptr<function, MxcLobe>, cosh_: ptr<function, f32>, above_1: ptr<function, bool>) -> vec3<f32> {
    var f: vec3<f32>;
    var param: MxcLobe;
    var param_1: bool;
    var param_2: f32;
    var param_3: f32;

    f = vec3<f32>(1f, 1f, 1f);
    let _e121 = (*l_2).kind;
    if (_e121 == 1i) {
        let _e123 = (*l_2);
        param = _e123;
        let _e124 = (*above_1);
        param_1 = _e124;
        let _e125 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param), (&param_1));
        let _e126 = (*cosh_);
        param_2 = _e126;
        param_3 = _e125;
        let _e127 = mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b((&param_2), (&param_3));
        f = vec3(_e127);
    }
    let _e129 = f;
    return _e129;
}

fn mxc_rough_alpha_u0028_vf2_u003b(alpha: ptr<function, vec2<f32>>) -> vec2<f32> {
    let _e113 = (*alpha);
    return max(_e113, vec2<f32>(0.0001f, 0.0001f));
}

fn mxc_ggx_d_u0028_vf3_u003b_vf2_u003b(m: ptr<function, vec3<f32>>, alpha_1: ptr<function, vec2<f32>>) -> f32 {
    var param_4: vec2<f32>;
    var s: vec3<f32>;
    var d: f32;

    let _e118 = (*m)[2u];
    if (_e118 <= 0f) {
        return 0f;
    }
    let _e120 = (*alpha_1);
    param_4 = _e120;
    let _e121 = mxc_rough_alpha_u0028_vf2_u003b((&param_4));
    (*alpha_1) = _e121;
    let _e123 = (*m)[0u];
    let _e125 = (*alpha_1)[0u];
    let _e128 = (*m)[1u];
    let _e130 = (*alpha_1)[1u];
    let _e133 = (*m)[2u];
    s = vec3<f32>((_e123 / _e125), (_e128 / _e130), _e133);
    let _e135 = s;
    let _e136 = s;
    d = dot(_e135, _e136);
    let _e139 = (*alpha_1)[0u];
    let _e142 = (*alpha_1)[1u];
    let _e144 = d;
    let _e146 = d;
    return (1f / ((((3.1415927f * _e139) * _e142) * _e144) * _e146));
}

fn mxc_sqr_u0028_f1_u003b(x: ptr<function, f32>) -> f32 {
    let _e113 = (*x);
    let _e114 = (*x);
    return (_e113 * _e114);
}

fn mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b(v: ptr<function, vec3<f32>>, alpha_2: ptr<function, vec2<f32>>) -> f32 {
    var param_5: vec2<f32>;
    var z2_: f32;
    var a2_: f32;
    var param_6: f32;
    var param_7: f32;

    let _e119 = (*alpha_2);
    param_5 = _e119;
    let _e120 = mxc_rough_alpha_u0028_vf2_u003b((&param_5));
    (*alpha_2) = _e120;
    let _e122 = (*v)[2u];
    let _e124 = (*v)[2u];
    z2_ = (_e122 * _e124);
    let _e126 = z2_;
    if (_e126 <= 0f) {
        return 10000000000f;
    }
    let _e129 = (*alpha_2)[0u];
    let _e131 = (*v)[0u];
    param_6 = (_e129 * _e131);
    let _e133 = mxc_sqr_u0028_f1_u003b((&param_6));
    let _e135 = (*alpha_2)[1u];
    let _e137 = (*v)[1u];
    param_7 = (_e135 * _e137);
    let _e139 = mxc_sqr_u0028_f1_u003b((&param_7));
    let _e141 = z2_;
    a2_ = ((_e133 + _e139) / _e141);
    let _e143 = a2_;
    return (0.5f * (-1f + sqrt((1f + _e143))));
}

fn mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b(v_1: ptr<function, vec3<f32>>, alpha_3: ptr<function, vec2<f32>>) -> f32 {
    var param_8: vec3<f32>;
    var param_9: vec2<f32>;

    let _e116 = (*v_1);
    param_8 = _e116;
    let _e117 = (*alpha_3);
    param_9 = _e117;
    let _e118 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_8), (&param_9));
    return (1f / (1f + _e118));
}

fn mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo: ptr<function, vec3<f32>>, m_1: ptr<function, vec3<f32>>, alpha_4: ptr<function, vec2<f32>>) -> f32 {
    var param_10: vec3<f32>;
    var param_11: vec2<f32>;
    var param_12: vec3<f32>;
    var param_13: vec2<f32>;

    let _e120 = (*wo)[2u];
    if (_e120 <= 0f) {
        return 0f;
    }
    let _e122 = (*wo);
    param_10 = _e122;
    let _e123 = (*alpha_4);
    param_11 = _e123;
    let _e124 = mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b((&param_10), (&param_11));
    let _e125 = (*wo);
    let _e126 = (*m_1);
    let _e130 = (*m_1);
    param_12 = _e130;
    let _e131 = (*alpha_4);
    param_13 = _e131;
    let _e132 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_12), (&param_13));
    let _e135 = (*wo)[2u];
    return (((_e124 * max(dot(_e125, _e126), 0f)) * _e132) / _e135);
}

fn mxc_is_delta_u0028_vf2_u003b(alpha_5: ptr<function, vec2<f32>>) -> bool {
    let _e114 = (*alpha_5)[0u];
    let _e116 = (*alpha_5)[1u];
    return (max(_e114, _e116) < 0.0001f);
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
    var phi_2334_: bool;
    var phi_2415_: bool;

    let _e134 = (*l_3).kind;
    switch _e134 {
        case 2, 3, 1: {
            let _e148 = (*l_3).alpha;
            param_14 = _e148;
            let _e149 = mxc_is_delta_u0028_vf2_u003b((&param_14));
            if _e149 {
                return 0f;
            }
            let _e151 = (*wo_1)[2u];
            above_2 = (_e151 > 0f);
            let _e153 = above_2;
            if _e153 {
                let _e154 = (*wo_1);
                local_1 = _e154;
            } else {
                let _e155 = (*wo_1);
                local_1 = -(_e155);
            }
            let _e157 = local_1;
            o = _e157;
            let _e158 = above_2;
            if _e158 {
                let _e159 = (*wi);
                local_2 = _e159;
            } else {
                let _e160 = (*wi);
                local_2 = -(_e160);
            }
            let _e162 = local_2;
            i = _e162;
            let _e164 = i[2u];
            if (_e164 > 0f) {
                let _e166 = o;
                let _e167 = i;
                h = normalize((_e166 + _e167));
                let _e170 = o;
                param_15 = _e170;
                let _e171 = h;
                param_16 = _e171;
                let _e173 = (*l_3).alpha;
                param_17 = _e173;
                let _e174 = mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_15), (&param_16), (&param_17));
                let _e175 = o;
                let _e176 = h;
                p = (_e174 / (4f * max(dot(_e175, _e176), 0.000001f)));
                let _e182 = (*l_3).kind;
                if (_e182 == 2i) {
                    let _e184 = p;
                    return _e184;
                }
                let _e186 = (*l_3).mode;
                if ((_e186 & 1i) == 0i) {
                    return 0f;
                }
                let _e189 = o;
                let _e190 = h;
                let _e193 = (*l_3);
                param_18 = _e193;
                param_19 = max(dot(_e189, _e190), 0f);
                let _e194 = above_2;
                param_20 = _e194;
                let _e195 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_18), (&param_19), (&param_20));
                param_21 = _e195;
                let _e196 = mxc_mean_u0028_vf3_u003b((&param_21));
                fr = _e196;
                let _e197 = p;
                let _e198 = (*l_3);
                param_22 = _e198;
                let _e199 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_22));
                phi_2415_ = _e199;
                if _e199 {
                    let _e201 = (*l_3).mode;
                    phi_2415_ = ((_e201 & 1i) != 0i);
                }
                let _e205 = phi_2415_;
                let _e206 = fr;
                return (_e197 * select(1f, _e206, _e205));
            }
            return 0f;
        }
        default: {
            let _e136 = (*wo_1)[2u];
            let _e137 = (_e136 > 0f);
            phi_2334_ = _e137;
            if _e137 {
                let _e139 = (*wi)[2u];
                phi_2334_ = (_e139 > 0f);
            }
            let _e142 = phi_2334_;
            if _e142 {
                let _e144 = (*wi)[2u];
                local_3 = (_e144 * 0.31830987f);
            } else {
                local_3 = 0f;
            }
            let _e146 = local_3;
            return _e146;
        }
    }
}

fn mxc_safe_sqrt_u0028_f1_u003b(x_1: ptr<function, f32>) -> f32 {
    let _e113 = (*x_1);
    return sqrt(max(_e113, 0f));
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

    let _e122 = (*sigma);
    a = (1f / (1f + (0.2877934f * _e122)));
    let _e126 = (*mu);
    c_2 = clamp(_e126, 0f, 1f);
    let _e128 = c_2;
    let _e129 = c_2;
    param_23 = (1f - (_e128 * _e129));
    let _e132 = mxc_safe_sqrt_u0028_f1_u003b((&param_23));
    s_1 = _e132;
    let _e133 = c_2;
    theta = acos(_e133);
    let _e135 = c_2;
    if (_e135 > 0.0001f) {
        let _e137 = s_1;
        let _e138 = s_1;
        let _e140 = s_1;
        let _e143 = c_2;
        local_4 = ((1f - ((_e137 * _e138) * _e140)) / _e143);
    } else {
        let _e145 = c_2;
        local_4 = (1.5f * _e145);
    }
    let _e147 = local_4;
    tail = _e147;
    let _e148 = s_1;
    let _e149 = theta;
    let _e150 = s_1;
    let _e151 = c_2;
    let _e155 = s_1;
    let _e157 = tail;
    let _e160 = s_1;
    g = (((_e148 * (_e149 - (_e150 * _e151))) + ((0.6666667f * _e155) * _e157)) - (0.6666667f * _e160));
    let _e163 = a;
    let _e164 = (*sigma);
    let _e165 = a;
    let _e167 = g;
    return (_e163 + (((_e164 * _e165) * _e167) * 0.31830987f));
}

fn mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b(sigma_1: ptr<function, f32>, wo_2: ptr<function, vec3<f32>>, wi_1: ptr<function, vec3<f32>>) -> f32 {
    var a_1: f32;
    var s_2: f32;
    var t: f32;
    var local_5: f32;

    let _e119 = (*sigma_1);
    a_1 = (1f / (1f + (0.2877934f * _e119)));
    let _e123 = (*wi_1);
    let _e124 = (*wo_2);
    let _e127 = (*wi_1)[2u];
    let _e129 = (*wo_2)[2u];
    s_2 = (dot(_e123, _e124) - (_e127 * _e129));
    let _e132 = s_2;
    if (_e132 > 0f) {
        let _e135 = (*wi_1)[2u];
        let _e137 = (*wo_2)[2u];
        local_5 = max(max(_e135, _e137), 0.000001f);
    } else {
        local_5 = 1f;
    }
    let _e140 = local_5;
    t = _e140;
    let _e141 = a_1;
    let _e142 = (*sigma_1);
    let _e143 = a_1;
    let _e145 = s_2;
    let _e147 = t;
    return ((_e141 + (((_e142 * _e143) * _e145) / _e147)) * 0.31830987f);
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

    let _e127 = (*rho);
    let _e128 = (*sigma_2);
    param_24 = _e128;
    let _e129 = (*wo_3);
    param_25 = _e129;
    let _e130 = (*wi_2);
    param_26 = _e130;
    let _e131 = mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b((&param_24), (&param_25), (&param_26));
    f_1 = (_e127 * _e131);
    let _e133 = (*sigma_2);
    a_2 = (1f / (1f + (0.2877934f * _e133)));
    let _e137 = a_2;
    let _e138 = (*sigma_2);
    eavg = (_e137 * (1f + (0.07248821f * _e138)));
    let _e142 = eavg;
    if (_e142 < 0.999999f) {
        let _e144 = (*rho);
        let _e145 = (*rho);
        let _e147 = eavg;
        let _e149 = eavg;
        let _e153 = (*rho);
        let _e154 = eavg;
        rhoMs = ((((_e144 * _e145) * _e147) / vec3((1f - _e149))) / (vec3(1f) - (_e153 * (1f - _e154))));
        let _e160 = rhoMs;
        let _e161 = (*sigma_2);
        param_27 = _e161;
        let _e163 = (*wi_2)[2u];
        param_28 = _e163;
        let _e164 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_27), (&param_28));
        let _e167 = (*sigma_2);
        param_29 = _e167;
        let _e169 = (*wo_3)[2u];
        param_30 = _e169;
        let _e170 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_29), (&param_30));
        let _e174 = f_1;
        f_1 = (_e174 + (((_e160 * (1f - _e164)) * (1f - _e170)) * 0.31830987f));
    }
    let _e176 = f_1;
    return _e176;
}

fn mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo_4: ptr<function, vec3<f32>>, wi_3: ptr<function, vec3<f32>>, alpha_6: ptr<function, vec2<f32>>) -> f32 {
    var param_31: vec3<f32>;
    var param_32: vec2<f32>;
    var param_33: vec3<f32>;
    var param_34: vec2<f32>;

    let _e119 = (*wo_4);
    param_31 = _e119;
    let _e120 = (*alpha_6);
    param_32 = _e120;
    let _e121 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_31), (&param_32));
    let _e123 = (*wi_3);
    param_33 = _e123;
    let _e124 = (*alpha_6);
    param_34 = _e124;
    let _e125 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_33), (&param_34));
    return (1f / ((1f + _e121) + _e125));
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
    var phi_1681_: bool;
    var phi_1688_: bool;

    let _e127 = (*wo_5)[2u];
    let _e128 = (_e127 <= 0f);
    phi_1681_ = _e128;
    if !(_e128) {
        let _e131 = (*wi_4)[2u];
        phi_1681_ = (_e131 <= 0f);
    }
    let _e134 = phi_1681_;
    phi_1688_ = _e134;
    if !(_e134) {
        let _e137 = (*l_4).alpha;
        param_35 = _e137;
        let _e138 = mxc_is_delta_u0028_vf2_u003b((&param_35));
        phi_1688_ = _e138;
    }
    let _e140 = phi_1688_;
    if _e140 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e141 = (*wo_5);
    let _e142 = (*wi_4);
    h_1 = normalize((_e141 + _e142));
    let _e145 = (*wo_5);
    let _e146 = h_1;
    let _e149 = (*l_4);
    param_36 = _e149;
    param_37 = max(dot(_e145, _e146), 0f);
    param_38 = true;
    let _e150 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_36), (&param_37), (&param_38));
    f_2 = _e150;
    let _e152 = (*l_4).kind;
    if (_e152 == 1i) {
        let _e155 = (*l_4).c0_;
        let _e156 = f_2;
        f_2 = (_e156 * _e155);
    }
    let _e158 = f_2;
    let _e159 = h_1;
    param_39 = _e159;
    let _e161 = (*l_4).alpha;
    param_40 = _e161;
    let _e162 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_39), (&param_40));
    let _e164 = (*wo_5);
    param_41 = _e164;
    let _e165 = (*wi_4);
    param_42 = _e165;
    let _e167 = (*l_4).alpha;
    param_43 = _e167;
    let _e168 = mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_41), (&param_42), (&param_43));
    let _e171 = (*wo_5)[2u];
    return (((_e158 * _e162) * _e168) / vec3((4f * _e171)));
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
    var phi_2268_: bool;
    var phi_2283_: bool;

    let _e131 = (*l_5).kind;
    switch _e131 {
        case 1: {
            let _e133 = (*wo_6)[2u];
            let _e135 = (*wi_5)[2u];
            if ((_e133 * _e135) > 0f) {
                let _e139 = (*l_5).mode;
                if ((_e139 & 1i) == 0i) {
                    return vec3<f32>(0f, 0f, 0f);
                }
                let _e143 = (*wo_6)[2u];
                if (_e143 < 0f) {
                    let _e145 = (*l_5);
                    m_2 = _e145;
                    let _e147 = (*l_5).eta;
                    m_2.eta = (1f / _e147);
                    m_2.c0_ = vec3<f32>(1f, 1f, 1f);
                    let _e151 = (*wo_6);
                    let _e153 = (*wi_5);
                    let _e155 = m_2;
                    param_44 = _e155;
                    param_45 = -(_e151);
                    param_46 = -(_e153);
                    let _e156 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_44), (&param_45), (&param_46));
                    return _e156;
                }
                let _e157 = (*l_5);
                param_47 = _e157;
                let _e158 = (*wo_6);
                param_48 = _e158;
                let _e159 = (*wi_5);
                param_49 = _e159;
                let _e160 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_47), (&param_48), (&param_49));
                return _e160;
            }
            return vec3<f32>(0f, 0f, 0f);
        }
        case 3, 2: {
            let _e162 = (*l_5).kind;
            let _e163 = (_e162 == 3i);
            phi_2268_ = _e163;
            if _e163 {
                let _e165 = (*l_5).mode;
                phi_2268_ = ((_e165 & 1i) == 0i);
            }
            let _e169 = phi_2268_;
            if _e169 {
                return vec3<f32>(0f, 0f, 0f);
            }
            let _e170 = (*l_5);
            param_50 = _e170;
            let _e171 = (*wo_6);
            param_51 = _e171;
            let _e172 = (*wi_5);
            param_52 = _e172;
            let _e173 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_50), (&param_51), (&param_52));
            return _e173;
        }
        case 5: {
            let _e175 = (*wo_6)[2u];
            let _e176 = (_e175 > 0f);
            phi_2283_ = _e176;
            if _e176 {
                let _e178 = (*wi_5)[2u];
                phi_2283_ = (_e178 > 0f);
            }
            let _e181 = phi_2283_;
            if _e181 {
                let _e183 = (*l_5).c0_;
                param_53 = _e183;
                let _e185 = (*l_5).p0_;
                param_54 = _e185;
                let _e186 = (*wo_6);
                param_55 = _e186;
                let _e187 = (*wi_5);
                param_56 = _e187;
                let _e188 = mxc_eon_u0028_vf3_u003b_f1_u003b_vf3_u003b_vf3_u003b((&param_53), (&param_54), (&param_55), (&param_56));
                let _e190 = (*wi_5)[2u];
                local_6 = (_e188 * _e190);
            } else {
                local_6 = vec3<f32>(0f, 0f, 0f);
            }
            let _e192 = local_6;
            return _e192;
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
    let _e114 = (*v_2);
    let _e116 = (*frame)[0];
    let _e118 = (*v_2);
    let _e120 = (*frame)[1];
    let _e122 = (*v_2);
    let _e124 = (*frame)[2];
    return vec3<f32>(dot(_e114, _e116), dot(_e118, _e120), dot(_e122, _e124));
}

fn mxc_frame_u0028_vf3_u003b_vf3_u003b(N: ptr<function, vec3<f32>>, T: ptr<function, vec3<f32>>) -> mat3x3<f32> {
    var t_1: vec3<f32>;
    var l2_: f32;
    var s_3: f32;
    var a_3: f32;
    var b: f32;

    let _e119 = (*T);
    let _e120 = (*N);
    let _e121 = (*N);
    let _e122 = (*T);
    t_1 = (_e119 - (_e120 * dot(_e121, _e122)));
    let _e126 = t_1;
    let _e127 = t_1;
    l2_ = dot(_e126, _e127);
    let _e129 = l2_;
    if !((_e129 > 0.000000000001f)) {
        let _e133 = (*N)[2u];
        s_3 = select(-1f, 1f, (_e133 >= 0f));
        let _e136 = s_3;
        let _e138 = (*N)[2u];
        a_3 = (-1f / (_e136 + _e138));
        let _e142 = (*N)[0u];
        let _e144 = (*N)[1u];
        let _e146 = a_3;
        b = ((_e142 * _e144) * _e146);
        let _e148 = s_3;
        let _e150 = (*N)[0u];
        let _e153 = (*N)[0u];
        let _e155 = a_3;
        let _e158 = s_3;
        let _e159 = b;
        let _e161 = s_3;
        let _e164 = (*N)[0u];
        t_1 = vec3<f32>((1f + (((_e148 * _e150) * _e153) * _e155)), (_e158 * _e159), (-(_e161) * _e164));
    } else {
        let _e167 = l2_;
        let _e169 = t_1;
        t_1 = (_e169 * inverseSqrt(_e167));
    }
    let _e171 = t_1;
    let _e172 = (*N);
    let _e173 = t_1;
    let _e174 = cross(_e172, _e173);
    let _e175 = (*N);
    return mat3x3<f32>(vec3<f32>(_e171.x, _e171.y, _e171.z), vec3<f32>(_e174.x, _e174.y, _e174.z), vec3<f32>(_e175.x, _e175.y, _e175.z));
}

fn mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b(c_3: ptr<function, MxcClosure>, wo_7: ptr<function, vec3<f32>>, wi_6: ptr<function, vec3<f32>>, wantPdf: ptr<function, bool>, pdf: ptr<function, f32>) -> vec3<f32> {
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
    var param_63: MxcLobe;
    var param_64: f32;
    var param_65: MxcLobe;
    var param_66: vec3<f32>;
    var param_67: vec3<f32>;
    var param_68: MxcLobe;
    var param_69: vec3<f32>;
    var param_70: vec3<f32>;
    var local_7: f32;

    f_3 = vec3<f32>(0f, 0f, 0f);
    p_1 = 0f;
    k = 0i;
    loop {
        let _e139 = k;
        let _e141 = (*c_3).count;
        if (_e139 < _e141) {
            let _e143 = k;
            let _e146 = (*c_3).lobes[_e143];
            l_7 = _e146;
            let _e148 = l_7.weight;
            if all((_e148 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e152 = l_7.N;
            param_57 = _e152;
            let _e154 = l_7.T;
            param_58 = _e154;
            let _e155 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_57), (&param_58));
            frame_1 = _e155;
            let _e156 = frame_1;
            param_59 = _e156;
            let _e157 = (*wo_7);
            param_60 = _e157;
            let _e158 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_59), (&param_60));
            o_1 = _e158;
            let _e159 = frame_1;
            param_61 = _e159;
            let _e160 = (*wi_6);
            param_62 = _e160;
            let _e161 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_61), (&param_62));
            i_1 = _e161;
            let _e163 = l_7.weight;
            let _e164 = k;
            let _e167 = (*c_3).ms[_e164];
            let _e170 = i_1[2u];
            let _e172 = l_7;
            param_63 = _e172;
            param_64 = abs(_e170);
            let _e173 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_63), (&param_64));
            let _e175 = l_7;
            param_65 = _e175;
            let _e176 = o_1;
            param_66 = _e176;
            let _e177 = i_1;
            param_67 = _e177;
            let _e178 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_65), (&param_66), (&param_67));
            let _e180 = f_3;
            f_3 = (_e180 + (((_e163 * _e167) * _e173) * _e178));
            let _e182 = (*wantPdf);
            if _e182 {
                let _e183 = k;
                let _e186 = (*c_3).choice[_e183];
                let _e187 = l_7;
                param_68 = _e187;
                let _e188 = o_1;
                param_69 = _e188;
                let _e189 = i_1;
                param_70 = _e189;
                let _e190 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_68), (&param_69), (&param_70));
                let _e192 = p_1;
                p_1 = (_e192 + (_e186 * _e190));
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e194 = k;
            k = (_e194 + 1i);
        }
    }
    let _e197 = (*c_3).choiceTotal;
    if (_e197 > 0f) {
        let _e199 = p_1;
        let _e201 = (*c_3).choiceTotal;
        local_7 = (_e199 / _e201);
    } else {
        local_7 = 0f;
    }
    let _e203 = local_7;
    (*pdf) = _e203;
    let _e204 = f_3;
    return _e204;
}

fn mxc_env_to_world_u0028_vf3_u003b_f1_u003b(m_3: ptr<function, vec3<f32>>, angle: ptr<function, f32>) -> vec3<f32> {
    var c_4: f32;
    var s_4: f32;

    let _e116 = (*angle);
    c_4 = cos(_e116);
    let _e118 = (*angle);
    s_4 = sin(_e118);
    let _e120 = c_4;
    let _e122 = (*m_3)[0u];
    let _e124 = s_4;
    let _e126 = (*m_3)[2u];
    let _e130 = (*m_3)[1u];
    let _e131 = s_4;
    let _e134 = (*m_3)[0u];
    let _e136 = c_4;
    let _e138 = (*m_3)[2u];
    return vec3<f32>(((_e120 * _e122) + (_e124 * _e126)), _e130, ((-(_e131) * _e134) + (_e136 * _e138)));
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

    let _e127 = unnamed.mxc_env_size;
    size = max(_e127.xy, vec2<u32>(1u, 1u));
    let _e131 = size[0u];
    let _e133 = size[1u];
    n = (_e131 * _e133);
    let _e136 = (*u)[0u];
    let _e137 = n;
    let _e141 = n;
    k_1 = min(u32((_e136 * f32(_e137))), (_e141 - 1u));
    let _e144 = k_1;
    let _e147 = unnamed.mxc_env_cells[_e144];
    cell = _e147;
    let _e149 = (*u)[1u];
    let _e151 = cell[0u];
    if (_e149 >= _e151) {
        let _e154 = cell[1u];
        let _e156 = n;
        k_1 = min(bitcast<u32>(_e154), (_e156 - 1u));
    }
    let _e159 = k_1;
    let _e163 = unnamed.mxc_env_cells[_e159][2u];
    (*pdf_1) = _e163;
    let _e164 = k_1;
    let _e166 = size[0u];
    i_2 = (_e164 % _e166);
    let _e168 = k_1;
    let _e170 = size[0u];
    j = (_e168 / _e170);
    let _e172 = i_2;
    let _e175 = (*u)[2u];
    let _e178 = size[0u];
    phi = (6.2831855f * (((f32(_e172) + _e175) / f32(_e178)) - 0.5f));
    let _e183 = j;
    let _e187 = size[1u];
    y0_ = cos(((3.1415927f * f32(_e183)) / f32(_e187)));
    let _e191 = j;
    let _e196 = size[1u];
    y1_ = cos(((3.1415927f * f32((_e191 + 1u))) / f32(_e196)));
    let _e200 = y0_;
    let _e201 = y1_;
    let _e203 = (*u)[3u];
    y = mix(_e200, _e201, _e203);
    let _e205 = y;
    let _e206 = y;
    param_71 = (1f - (_e205 * _e206));
    let _e209 = mxc_safe_sqrt_u0028_f1_u003b((&param_71));
    r = _e209;
    let _e210 = r;
    let _e211 = phi;
    let _e214 = y;
    let _e215 = r;
    let _e217 = phi;
    return vec3<f32>((_e210 * sin(_e211)), _e214, (-(_e215) * cos(_e217)));
}

fn mxc_power_heuristic_u0028_f1_u003b_f1_u003b(a_4: ptr<function, f32>, b_1: ptr<function, f32>) -> f32 {
    var a2_1: f32;
    var b2_: f32;
    var local_8: f32;

    let _e117 = (*a_4);
    let _e118 = (*a_4);
    a2_1 = (_e117 * _e118);
    let _e120 = (*b_1);
    let _e121 = (*b_1);
    b2_ = (_e120 * _e121);
    let _e123 = a2_1;
    let _e124 = b2_;
    if ((_e123 + _e124) > 0f) {
        let _e127 = a2_1;
        let _e128 = a2_1;
        let _e129 = b2_;
        local_8 = (_e127 / (_e128 + _e129));
    } else {
        local_8 = 0f;
    }
    let _e132 = local_8;
    return _e132;
}

fn mxc_env_uv_u0028_vf3_u003b(d_1: ptr<function, vec3<f32>>) -> vec2<f32> {
    var u_1: f32;
    var local_9: f32;
    var v_3: f32;

    let _e117 = (*d_1)[0u];
    let _e120 = (*d_1)[2u];
    if ((abs(_e117) + abs(_e120)) > 0.000000000001f) {
        let _e125 = (*d_1)[0u];
        let _e127 = (*d_1)[2u];
        local_9 = (0.5f + (atan2(_e125, -(_e127)) * 0.15915494f));
    } else {
        local_9 = 0.5f;
    }
    let _e132 = local_9;
    u_1 = _e132;
    let _e133 = (*d_1);
    let _e137 = (*d_1)[1u];
    v_3 = (atan2(length(_e133.xz), _e137) * 0.31830987f);
    let _e140 = u_1;
    let _e141 = v_3;
    return vec2<f32>(_e140, _e141);
}

fn mxc_env_cell_u0028_vf3_u003b(d_2: ptr<function, vec3<f32>>) -> u32 {
    var uv: vec2<f32>;
    var param_72: vec3<f32>;
    var size_1: vec2<u32>;
    var i_3: u32;
    var j_1: u32;

    let _e118 = (*d_2);
    param_72 = _e118;
    let _e119 = mxc_env_uv_u0028_vf3_u003b((&param_72));
    uv = _e119;
    let _e121 = unnamed.mxc_env_size;
    size_1 = max(_e121.xy, vec2<u32>(1u, 1u));
    let _e125 = uv[0u];
    let _e128 = size_1[0u];
    let _e133 = size_1[0u];
    i_3 = min(u32((max(_e125, 0f) * f32(_e128))), (_e133 - 1u));
    let _e137 = uv[1u];
    let _e140 = size_1[1u];
    let _e145 = size_1[1u];
    j_1 = min(u32((max(_e137, 0f) * f32(_e140))), (_e145 - 1u));
    let _e148 = j_1;
    let _e150 = size_1[0u];
    let _e152 = i_3;
    return ((_e148 * _e150) + _e152);
}

fn mxc_env_pdf_u0028_vf3_u003b(d_3: ptr<function, vec3<f32>>) -> f32 {
    var param_73: vec3<f32>;

    let _e114 = (*d_3);
    param_73 = _e114;
    let _e115 = mxc_env_cell_u0028_vf3_u003b((&param_73));
    let _e119 = unnamed.mxc_env_cells[_e115][2u];
    return _e119;
}

fn mxc_env_to_map_u0028_vf3_u003b_f1_u003b(w: ptr<function, vec3<f32>>, angle_1: ptr<function, f32>) -> vec3<f32> {
    var c_5: f32;
    var s_5: f32;

    let _e116 = (*angle_1);
    c_5 = cos(_e116);
    let _e118 = (*angle_1);
    s_5 = sin(_e118);
    let _e120 = c_5;
    let _e122 = (*w)[0u];
    let _e124 = s_5;
    let _e126 = (*w)[2u];
    let _e130 = (*w)[1u];
    let _e131 = s_5;
    let _e133 = (*w)[0u];
    let _e135 = c_5;
    let _e137 = (*w)[2u];
    return vec3<f32>(((_e120 * _e122) - (_e124 * _e126)), _e130, ((_e131 * _e133) + (_e135 * _e137)));
}

fn mxc_env_lookup_u0028_vf3_u003b(d_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_74: vec3<f32>;

    let _e114 = (*d_4);
    param_74 = _e114;
    let _e115 = mxc_env_uv_u0028_vf3_u003b((&param_74));
    let _e116 = textureSampleLevel(mxc_env_radiance_texture, mxc_env_radiance_sampler, _e115, 0f);
    return _e116.xyz;
}

fn mxc_sky_u0028_vf3_u003b(d_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var y_1: f32;
    var horizon: vec3<f32>;
    var zenith: vec3<f32>;
    var ground: vec3<f32>;

    let _e118 = (*d_5)[1u];
    y_1 = clamp(_e118, -1f, 1f);
    horizon = vec3<f32>(1f, 0.96f, 0.9f);
    zenith = vec3<f32>(0.3f, 0.5f, 0.95f);
    ground = vec3<f32>(0.16f, 0.145f, 0.13f);
    let _e120 = y_1;
    if (_e120 >= 0f) {
        let _e122 = horizon;
        let _e123 = zenith;
        let _e124 = y_1;
        return mix(_e122, _e123, vec3(sqrt(_e124)));
    }
    let _e128 = horizon;
    let _e129 = ground;
    let _e130 = y_1;
    return mix(_e128, _e129, vec3(sqrt(-(_e130))));
}

fn mxc_environment_code_u0028_() -> i32 {
    var local_10: i32;

    if false {
        local_10 = MXC_ENVIRONMENT;
    } else {
        let _e115 = mxc_view.counts[1u];
        local_10 = _e115;
    }
    let _e116 = local_10;
    return _e116;
}

fn mxc_environment_u0028_vf3_u003b(d_6: ptr<function, vec3<f32>>) -> vec3<f32> {
    var code: i32;
    var param_75: vec3<f32>;
    var param_76: vec3<f32>;
    var param_77: f32;
    var param_78: vec3<f32>;

    let _e118 = mxc_environment_code_u0028_();
    code = _e118;
    let _e119 = code;
    if (_e119 == 1i) {
        let _e123 = mxc_view.environment[0u];
        return vec3(_e123);
    }
    let _e125 = code;
    if (_e125 == 2i) {
        let _e129 = mxc_view.environment[0u];
        let _e130 = (*d_6);
        param_75 = _e130;
        let _e131 = mxc_sky_u0028_vf3_u003b((&param_75));
        return (_e131 * _e129);
    }
    let _e133 = code;
    if (_e133 == 3i) {
        let _e137 = mxc_view.environment[0u];
        let _e138 = (*d_6);
        param_76 = _e138;
        let _e141 = mxc_view.environment[2u];
        param_77 = _e141;
        let _e142 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_76), (&param_77));
        param_78 = _e142;
        let _e143 = mxc_env_lookup_u0028_vf3_u003b((&param_78));
        return (_e143 * _e137);
    }
    return vec3<f32>(0f, 0f, 0f);
}

fn mxc_exit_direction_u0028_vf3_u003b_vf3_u003b(d_7: ptr<function, vec3<f32>>, t_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var axis: vec3<f32>;
    var s_6: f32;
    var c_6: f32;

    let _e117 = (*d_7);
    let _e118 = (*t_2);
    axis = cross(_e117, _e118);
    let _e120 = axis;
    s_6 = length(_e120);
    let _e122 = s_6;
    if (_e122 < 0.000001f) {
        let _e124 = (*t_2);
        return _e124;
    }
    let _e125 = s_6;
    let _e126 = axis;
    axis = (_e126 / vec3(_e125));
    let _e129 = (*d_7);
    let _e130 = (*t_2);
    c_6 = dot(_e129, _e130);
    let _e132 = (*t_2);
    let _e133 = c_6;
    let _e135 = axis;
    let _e136 = (*t_2);
    let _e138 = s_6;
    let _e141 = axis;
    let _e142 = axis;
    let _e143 = (*t_2);
    let _e146 = c_6;
    return (((_e132 * _e133) + (cross(_e135, _e136) * _e138)) + ((_e141 * dot(_e142, _e143)) * (1f - _e146)));
}

fn mxc_to_world_u0028_mf33_u003b_vf3_u003b(frame_2: ptr<function, mat3x3<f32>>, v_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e115 = (*frame_2)[0];
    let _e117 = (*v_4)[0u];
    let _e120 = (*frame_2)[1];
    let _e122 = (*v_4)[1u];
    let _e126 = (*frame_2)[2];
    let _e128 = (*v_4)[2u];
    return (((_e115 * _e117) + (_e120 * _e122)) + (_e126 * _e128));
}

fn mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b(wo_8: ptr<function, vec3<f32>>, alpha_7: ptr<function, vec2<f32>>, u_2: ptr<function, vec2<f32>>) -> vec3<f32> {
    var param_79: vec2<f32>;
    var vh: vec3<f32>;
    var lensq: f32;
    var t1_: vec3<f32>;
    var local_11: vec3<f32>;
    var t2_: vec3<f32>;
    var r_1: f32;
    var phi_1: f32;
    var p1_: f32;
    var p2_: f32;
    var s_7: f32;
    var param_80: f32;
    var nh: vec3<f32>;
    var param_81: f32;

    let _e129 = (*alpha_7);
    param_79 = _e129;
    let _e130 = mxc_rough_alpha_u0028_vf2_u003b((&param_79));
    (*alpha_7) = _e130;
    let _e132 = (*alpha_7)[0u];
    let _e134 = (*wo_8)[0u];
    let _e137 = (*alpha_7)[1u];
    let _e139 = (*wo_8)[1u];
    let _e142 = (*wo_8)[2u];
    vh = normalize(vec3<f32>((_e132 * _e134), (_e137 * _e139), _e142));
    let _e146 = vh[0u];
    let _e148 = vh[0u];
    let _e151 = vh[1u];
    let _e153 = vh[1u];
    lensq = ((_e146 * _e148) + (_e151 * _e153));
    let _e156 = lensq;
    if (_e156 > 0f) {
        let _e159 = vh[1u];
        let _e162 = vh[0u];
        let _e164 = lensq;
        local_11 = (vec3<f32>(-(_e159), _e162, 0f) * inverseSqrt(_e164));
    } else {
        local_11 = vec3<f32>(1f, 0f, 0f);
    }
    let _e167 = local_11;
    t1_ = _e167;
    let _e168 = vh;
    let _e169 = t1_;
    t2_ = cross(_e168, _e169);
    let _e172 = (*u_2)[0u];
    r_1 = sqrt(_e172);
    let _e175 = (*u_2)[1u];
    phi_1 = (6.2831855f * _e175);
    let _e177 = r_1;
    let _e178 = phi_1;
    p1_ = (_e177 * cos(_e178));
    let _e181 = r_1;
    let _e182 = phi_1;
    p2_ = (_e181 * sin(_e182));
    let _e186 = vh[2u];
    s_7 = (0.5f * (1f + _e186));
    let _e189 = s_7;
    let _e191 = p1_;
    let _e192 = p1_;
    param_80 = (1f - (_e191 * _e192));
    let _e195 = mxc_safe_sqrt_u0028_f1_u003b((&param_80));
    let _e197 = s_7;
    let _e198 = p2_;
    p2_ = (((1f - _e189) * _e195) + (_e197 * _e198));
    let _e201 = p1_;
    let _e202 = t1_;
    let _e204 = p2_;
    let _e205 = t2_;
    let _e208 = p1_;
    let _e209 = p1_;
    let _e212 = p2_;
    let _e213 = p2_;
    param_81 = ((1f - (_e208 * _e209)) - (_e212 * _e213));
    let _e216 = mxc_safe_sqrt_u0028_f1_u003b((&param_81));
    let _e217 = vh;
    nh = (((_e202 * _e201) + (_e205 * _e204)) + (_e217 * _e216));
    let _e221 = (*alpha_7)[0u];
    let _e223 = nh[0u];
    let _e226 = (*alpha_7)[1u];
    let _e228 = nh[1u];
    let _e231 = nh[2u];
    return normalize(vec3<f32>((_e221 * _e223), (_e226 * _e228), max(_e231, 0f)));
}

fn mxc_sample_cosine_u0028_vf2_u003b(u_3: ptr<function, vec2<f32>>) -> vec3<f32> {
    var r_2: f32;
    var phi_2: f32;
    var param_82: f32;

    let _e117 = (*u_3)[0u];
    r_2 = sqrt(_e117);
    let _e120 = (*u_3)[1u];
    phi_2 = (6.2831855f * _e120);
    let _e122 = r_2;
    let _e123 = phi_2;
    let _e126 = r_2;
    let _e127 = phi_2;
    let _e131 = (*u_3)[0u];
    param_82 = (1f - _e131);
    let _e133 = mxc_safe_sqrt_u0028_f1_u003b((&param_82));
    return vec3<f32>((_e122 * cos(_e123)), (_e126 * sin(_e127)), _e133);
}

fn mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_8: ptr<function, MxcLobe>, wo_9: ptr<function, vec3<f32>>, u_4: ptr<function, vec3<f32>>) -> MxcLobeSample {
    var s_8: MxcLobeSample;
    var above_3: bool;
    var o_2: vec3<f32>;
    var local_12: vec3<f32>;
    var delta: bool;
    var param_83: vec2<f32>;
    var m_4: vec3<f32>;
    var local_13: vec3<f32>;
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
    var local_14: f32;
    var param_91: vec3<f32>;
    var pReflect: f32;
    var local_15: f32;
    var i_4: vec3<f32>;
    var local_16: vec3<f32>;
    var tint: vec3<f32>;
    var local_17: vec3<f32>;
    var local_18: vec3<f32>;
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
    var phi_2546_: bool;
    var phi_2551_: bool;
    var phi_2562_: bool;

    s_8.valid = false;
    s_8.delta = false;
    s_8.pdf = 0f;
    s_8.value = vec3<f32>(0f, 0f, 0f);
    s_8.wi = vec3<f32>(0f, 0f, 1f);
    let _e163 = (*l_8).kind;
    switch _e163 {
        case 2, 3, 1: {
            let _e190 = (*wo_9)[2u];
            above_3 = (_e190 > 0f);
            let _e192 = above_3;
            if _e192 {
                let _e193 = (*wo_9);
                local_12 = _e193;
            } else {
                let _e194 = (*wo_9);
                local_12 = -(_e194);
            }
            let _e196 = local_12;
            o_2 = _e196;
            let _e198 = o_2[2u];
            if (_e198 <= 0f) {
                let _e200 = s_8;
                return _e200;
            }
            let _e202 = (*l_8).alpha;
            param_83 = _e202;
            let _e203 = mxc_is_delta_u0028_vf2_u003b((&param_83));
            delta = _e203;
            let _e204 = delta;
            if _e204 {
                local_13 = vec3<f32>(0f, 0f, 1f);
            } else {
                let _e205 = o_2;
                param_84 = _e205;
                let _e207 = (*l_8).alpha;
                param_85 = _e207;
                let _e208 = (*u_4);
                param_86 = _e208.xy;
                let _e210 = mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b((&param_84), (&param_85), (&param_86));
                local_13 = _e210;
            }
            let _e211 = local_13;
            m_4 = _e211;
            let _e212 = o_2;
            let _e213 = m_4;
            hm = dot(_e212, _e213);
            let _e216 = (*l_8).kind;
            let _e217 = (_e216 == 1i);
            phi_2546_ = _e217;
            if !(_e217) {
                let _e220 = (*l_8).kind;
                phi_2546_ = (_e220 == 3i);
            }
            let _e223 = phi_2546_;
            phi_2551_ = _e223;
            if _e223 {
                let _e224 = (*l_8);
                param_87 = _e224;
                let _e225 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_87));
                phi_2551_ = _e225;
            }
            let _e227 = phi_2551_;
            transmits = _e227;
            let _e229 = (*l_8).kind;
            let _e230 = (_e229 == 2i);
            phi_2562_ = _e230;
            if !(_e230) {
                let _e233 = (*l_8).mode;
                phi_2562_ = ((_e233 & 1i) != 0i);
            }
            let _e237 = phi_2562_;
            reflects = _e237;
            let _e238 = hm;
            let _e240 = (*l_8);
            param_88 = _e240;
            param_89 = max(_e238, 0f);
            let _e241 = above_3;
            param_90 = _e241;
            let _e242 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_88), (&param_89), (&param_90));
            f_4 = _e242;
            let _e243 = transmits;
            if _e243 {
                let _e244 = f_4;
                param_91 = _e244;
                let _e245 = mxc_mean_u0028_vf3_u003b((&param_91));
                local_14 = _e245;
            } else {
                local_14 = 1f;
            }
            let _e246 = local_14;
            fr_1 = _e246;
            let _e247 = transmits;
            if _e247 {
                let _e248 = reflects;
                let _e249 = fr_1;
                local_15 = select(0f, _e249, _e248);
            } else {
                local_15 = 1f;
            }
            let _e251 = local_15;
            pReflect = _e251;
            let _e253 = (*u_4)[2u];
            let _e254 = pReflect;
            if (_e253 < _e254) {
                let _e256 = o_2;
                let _e258 = m_4;
                i_4 = reflect(-(_e256), _e258);
                let _e261 = i_4[2u];
                if (_e261 <= 0f) {
                    let _e263 = s_8;
                    return _e263;
                }
                let _e264 = above_3;
                if _e264 {
                    let _e265 = i_4;
                    local_16 = _e265;
                } else {
                    let _e266 = i_4;
                    local_16 = -(_e266);
                }
                let _e268 = local_16;
                s_8.wi = _e268;
                let _e270 = delta;
                s_8.delta = _e270;
                let _e272 = delta;
                if _e272 {
                    let _e274 = (*l_8).kind;
                    if (_e274 == 1i) {
                        let _e276 = above_3;
                        if _e276 {
                            let _e278 = (*l_8).c0_;
                            local_18 = _e278;
                        } else {
                            local_18 = vec3<f32>(1f, 1f, 1f);
                        }
                        let _e279 = local_18;
                        local_17 = _e279;
                    } else {
                        local_17 = vec3<f32>(1f, 1f, 1f);
                    }
                    let _e280 = local_17;
                    tint = _e280;
                    let _e281 = f_4;
                    let _e282 = tint;
                    s_8.value = (_e281 * _e282);
                    let _e285 = pReflect;
                    s_8.pdf = _e285;
                } else {
                    let _e287 = (*l_8);
                    param_92 = _e287;
                    let _e288 = (*wo_9);
                    param_93 = _e288;
                    let _e290 = s_8.wi;
                    param_94 = _e290;
                    let _e291 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_92), (&param_93), (&param_94));
                    s_8.value = _e291;
                    let _e293 = (*l_8);
                    param_95 = _e293;
                    let _e294 = (*wo_9);
                    param_96 = _e294;
                    let _e296 = s_8.wi;
                    param_97 = _e296;
                    let _e297 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_95), (&param_96), (&param_97));
                    s_8.pdf = _e297;
                }
                let _e300 = s_8.pdf;
                s_8.valid = (_e300 > 0f);
                let _e303 = s_8;
                return _e303;
            }
            let _e304 = s_8;
            return _e304;
        }
        default: {
            let _e165 = (*wo_9)[2u];
            if (_e165 <= 0f) {
                let _e167 = s_8;
                return _e167;
            }
            let _e168 = (*u_4);
            param_98 = _e168.xy;
            let _e170 = mxc_sample_cosine_u0028_vf2_u003b((&param_98));
            s_8.wi = _e170;
            let _e172 = (*l_8);
            param_99 = _e172;
            let _e173 = (*wo_9);
            param_100 = _e173;
            let _e175 = s_8.wi;
            param_101 = _e175;
            let _e176 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_99), (&param_100), (&param_101));
            s_8.value = _e176;
            let _e178 = (*l_8);
            param_102 = _e178;
            let _e179 = (*wo_9);
            param_103 = _e179;
            let _e181 = s_8.wi;
            param_104 = _e181;
            let _e182 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_102), (&param_103), (&param_104));
            s_8.pdf = _e182;
            let _e185 = s_8.pdf;
            s_8.valid = (_e185 > 0f);
            let _e188 = s_8;
            return _e188;
        }
    }
}

fn mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b(c_7: ptr<function, MxcClosure>, wo_10: ptr<function, vec3<f32>>, u_5: ptr<function, vec3<f32>>) -> MxcSample {
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
    let _e146 = (*wo_10);
    s_9.wi = _e146;
    let _e149 = (*c_7).choiceTotal;
    total = _e149;
    let _e151 = (*c_7).count;
    let _e153 = total;
    if ((_e151 == 0i) || (_e153 <= 0f)) {
        let _e156 = s_9;
        return _e156;
    }
    let _e158 = (*u_5)[2u];
    let _e159 = total;
    x_2 = (_e158 * _e159);
    chosen = -1i;
    before = 0f;
    p_2 = 0f;
    lastBefore = 0f;
    last = -1i;
    k_2 = 0i;
    loop {
        let _e161 = k_2;
        let _e163 = (*c_7).count;
        if (_e161 < _e163) {
            let _e165 = k_2;
            let _e168 = (*c_7).choice[_e165];
            pk = _e168;
            let _e169 = pk;
            if (_e169 <= 0f) {
                continue;
            }
            let _e171 = x_2;
            let _e172 = before;
            let _e173 = pk;
            if (_e171 < (_e172 + _e173)) {
                let _e176 = k_2;
                chosen = _e176;
                let _e177 = pk;
                p_2 = _e177;
                break;
            }
            let _e178 = k_2;
            last = _e178;
            let _e179 = before;
            lastBefore = _e179;
            let _e180 = pk;
            let _e181 = before;
            before = (_e181 + _e180);
            continue;
        } else {
            break;
        }
        continuing {
            let _e183 = k_2;
            k_2 = (_e183 + 1i);
        }
    }
    let _e185 = chosen;
    if (_e185 < 0i) {
        let _e187 = last;
        chosen = max(_e187, 0i);
        let _e189 = chosen;
        let _e192 = (*c_7).choice[_e189];
        p_2 = _e192;
        let _e193 = lastBefore;
        before = _e193;
    }
    let _e194 = p_2;
    if (_e194 <= 0f) {
        let _e196 = s_9;
        return _e196;
    }
    let _e197 = x_2;
    let _e198 = before;
    let _e200 = p_2;
    uz = clamp(((_e197 - _e198) / _e200), 0f, 0.99999994f);
    let _e203 = chosen;
    let _e206 = (*c_7).lobes[_e203];
    l_9 = _e206;
    let _e208 = l_9.N;
    param_105 = _e208;
    let _e210 = l_9.T;
    param_106 = _e210;
    let _e211 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_105), (&param_106));
    frame_3 = _e211;
    let _e212 = frame_3;
    param_107 = _e212;
    let _e213 = (*wo_10);
    param_108 = _e213;
    let _e214 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_107), (&param_108));
    o_3 = _e214;
    let _e215 = (*u_5);
    let _e216 = _e215.xy;
    let _e217 = uz;
    let _e221 = l_9;
    param_109 = _e221;
    let _e222 = o_3;
    param_110 = _e222;
    param_111 = vec3<f32>(_e216.x, _e216.y, _e217);
    let _e223 = mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_109), (&param_110), (&param_111));
    ls = _e223;
    let _e225 = ls.valid;
    if !(_e225) {
        let _e227 = s_9;
        return _e227;
    }
    let _e228 = frame_3;
    param_112 = _e228;
    let _e230 = ls.wi;
    param_113 = _e230;
    let _e231 = mxc_to_world_u0028_mf33_u003b_vf3_u003b((&param_112), (&param_113));
    s_9.wi = _e231;
    let _e234 = ls.delta;
    if _e234 {
        s_9.delta = true;
        let _e237 = ls.pdf;
        let _e238 = p_2;
        let _e240 = total;
        s_9.pdf = ((_e237 * _e238) / _e240);
        let _e244 = l_9.weight;
        let _e245 = chosen;
        let _e248 = (*c_7).ms[_e245];
        let _e252 = ls.wi[2u];
        let _e254 = l_9;
        param_114 = _e254;
        param_115 = abs(_e252);
        let _e255 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_114), (&param_115));
        let _e258 = ls.value;
        let _e261 = s_9.pdf;
        s_9.weight = ((((_e244 * _e248) * _e255) * _e258) / vec3(_e261));
        let _e266 = s_9.pdf;
        s_9.valid = (_e266 > 0f);
        let _e269 = s_9;
        return _e269;
    }
    s_9.evaluate = true;
    s_9.valid = true;
    let _e272 = s_9;
    return _e272;
}

fn mxc_radical_inverse_u0028_u1_u003b_u1_u003b(i_5: ptr<function, u32>, base: ptr<function, u32>) -> f32 {
    var inv: f32;
    var f_5: f32;
    var r_3: f32;

    let _e117 = (*base);
    if (_e117 == 2u) {
        let _e119 = (*i_5);
        return (f32((reverseBits(_e119) >> bitcast<u32>(8i))) * 0.000000059604645f);
    }
    let _e125 = (*base);
    inv = (1f / f32(_e125));
    let _e128 = inv;
    f_5 = _e128;
    r_3 = 0f;
    loop {
        let _e129 = (*i_5);
        if (_e129 > 0u) {
            let _e131 = f_5;
            let _e132 = (*i_5);
            let _e133 = (*base);
            let _e137 = r_3;
            r_3 = (_e137 + (_e131 * f32((_e132 % _e133))));
            let _e139 = inv;
            let _e140 = f_5;
            f_5 = (_e140 * _e139);
            continue;
        } else {
            break;
        }
        continuing {
            let _e142 = (*base);
            let _e143 = (*i_5);
            (*i_5) = (_e143 / _e142);
        }
    }
    let _e145 = r_3;
    return min(_e145, 0.99999994f);
}

fn mxc_pcg_u0028_u1_u003b(v_5: ptr<function, u32>) -> u32 {
    var state: u32;
    var word: u32;

    let _e115 = (*v_5);
    state = ((_e115 * 747796405u) + 2891336453u);
    let _e118 = state;
    let _e119 = state;
    let _e125 = state;
    word = (((_e118 >> bitcast<u32>(((_e119 >> bitcast<u32>(28u)) + 4u))) ^ _e125) * 277803737u);
    let _e128 = word;
    let _e131 = word;
    return ((_e128 >> bitcast<u32>(22u)) ^ _e131);
}

fn mxc_uniform_u0028_u1_u003b(seed: ptr<function, u32>) -> f32 {
    var param_116: u32;

    let _e114 = (*seed);
    param_116 = _e114;
    let _e115 = mxc_pcg_u0028_u1_u003b((&param_116));
    (*seed) = _e115;
    let _e116 = (*seed);
    return (f32((_e116 >> bitcast<u32>(8i))) * 0.000000059604645f);
}

fn mxc_light_kinds_u0028_() -> i32 {
    return 7i;
}

fn mxc_light_count_u0028_() -> i32 {
    var local_19: i32;

    if false {
        local_19 = MXC_LIGHT_COUNT;
    } else {
        let _e115 = mxc_view.counts[0u];
        local_19 = _e115;
    }
    let _e116 = local_19;
    return min(_e116, 8i);
}

fn mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b(mu_2: ptr<function, f32>, x_3: ptr<function, f32>, firstRow: ptr<function, f32>) -> vec4<f32> {
    var t_3: vec2<f32>;

    let _e116 = (*mu_2);
    let _e119 = (*x_3);
    t_3 = ((vec2<f32>(sqrt(clamp(_e116, 0f, 1f)), clamp(_e119, 0f, 1f)) * 31f) + vec2(0.5f));
    let _e126 = t_3[0u];
    let _e128 = (*firstRow);
    let _e130 = t_3[1u];
    let _e134 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, vec2<f32>((_e126 / 32f), ((_e128 + _e130) / 1654f)), 0f);
    return _e134;
}

fn mxc_table_u0028_f1_u003b_f1_u003b(mu_3: ptr<function, f32>, x_4: ptr<function, f32>) -> vec4<f32> {
    var param_117: f32;
    var param_118: f32;
    var param_119: f32;

    let _e117 = (*mu_3);
    param_117 = _e117;
    let _e118 = (*x_4);
    param_118 = _e118;
    param_119 = 0f;
    let _e119 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_117), (&param_118), (&param_119));
    return _e119;
}

fn mxc_split_sum_u0028_f1_u003b_f1_u003b(mu_4: ptr<function, f32>, alpha_8: ptr<function, f32>) -> vec2<f32> {
    var param_120: f32;
    var param_121: f32;

    let _e116 = (*alpha_8);
    let _e119 = (*mu_4);
    param_120 = _e119;
    param_121 = sqrt(max(_e116, 0f));
    let _e120 = mxc_table_u0028_f1_u003b_f1_u003b((&param_120), (&param_121));
    return _e120.xy;
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

    let _e126 = (*e);
    s_10 = (sqrt(clamp((0.5f * (_e126 - 1f)), 0f, 1f)) * 31f);
    let _e132 = s_10;
    s0_ = min(floor(_e132), 30f);
    let _e135 = (*alpha_9);
    x_5 = sqrt(max(_e135, 0f));
    let _e138 = s0_;
    let _e141 = (*mu_5);
    param_122 = _e141;
    let _e142 = x_5;
    param_123 = _e142;
    param_124 = (32f * (1f + _e138));
    let _e143 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_122), (&param_123), (&param_124));
    a_5 = _e143;
    let _e144 = s0_;
    let _e147 = (*mu_5);
    param_125 = _e147;
    let _e148 = x_5;
    param_126 = _e148;
    param_127 = (32f * (2f + _e144));
    let _e149 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_125), (&param_126), (&param_127));
    b_2 = _e149;
    let _e150 = a_5;
    let _e151 = b_2;
    let _e152 = s_10;
    let _e153 = s0_;
    return mix(_e150, _e151, vec4((_e152 - _e153)));
}

fn mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b(mu_6: ptr<function, f32>, alpha_10: ptr<function, f32>, eta_1: ptr<function, f32>) -> f32 {
    var e_1: f32;
    var local_20: f32;
    var param_128: f32;
    var param_129: f32;
    var param_130: f32;

    let _e120 = (*eta_1);
    if (_e120 >= 1f) {
        let _e122 = (*eta_1);
        local_20 = _e122;
    } else {
        let _e123 = (*eta_1);
        local_20 = (1f / max(_e123, 0.001f));
    }
    let _e126 = local_20;
    e_1 = _e126;
    let _e127 = (*mu_6);
    param_128 = _e127;
    let _e128 = (*alpha_10);
    param_129 = _e128;
    let _e129 = e_1;
    param_130 = _e129;
    let _e130 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_128), (&param_129), (&param_130));
    return _e130.x;
}

fn mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_10: ptr<function, MxcLobe>, wo_11: ptr<function, vec3<f32>>, ms: ptr<function, vec3<f32>>) -> vec3<f32> {
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
    var local_21: vec3<f32>;
    var param_143: vec2<f32>;
    var param_144: MxcLobe;
    var param_145: f32;
    var param_146: bool;
    var phi_2059_: bool;
    var phi_2066_: bool;
    var phi_2084_: bool;

    let _e140 = (*wo_11)[2u];
    mu_7 = clamp(_e140, 0f, 1f);
    let _e143 = (*l_10).kind;
    let _e144 = (_e143 == 1i);
    phi_2059_ = _e144;
    if !(_e144) {
        let _e147 = (*l_10).kind;
        phi_2059_ = (_e147 == 2i);
    }
    let _e150 = phi_2059_;
    phi_2066_ = _e150;
    if !(_e150) {
        let _e153 = (*l_10).kind;
        phi_2066_ = (_e153 == 3i);
    }
    let _e156 = phi_2066_;
    if _e156 {
        let _e159 = (*l_10).alpha[0u];
        let _e162 = (*l_10).alpha[1u];
        alpha_11 = sqrt((_e159 * _e162));
        let _e166 = (*l_10).kind;
        let _e167 = (_e166 == 1i);
        phi_2084_ = _e167;
        if _e167 {
            let _e169 = (*l_10).alpha;
            param_131 = _e169;
            let _e170 = mxc_is_delta_u0028_vf2_u003b((&param_131));
            phi_2084_ = !(_e170);
        }
        let _e173 = phi_2084_;
        if _e173 {
            let _e174 = mu_7;
            param_132 = _e174;
            let _e175 = alpha_11;
            param_133 = _e175;
            let _e177 = (*l_10).eta;
            param_134 = _e177;
            let _e178 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_132), (&param_133), (&param_134));
            e_2 = vec3(_e178);
            let _e180 = e_2;
            let _e182 = (*l_10).c0_;
            let _e184 = (*ms);
            return clamp(((_e180 * _e182) * _e184), vec3(0f), vec3(1f));
        }
        let _e189 = mu_7;
        param_135 = _e189;
        let _e190 = alpha_11;
        param_136 = _e190;
        let _e191 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_135), (&param_136));
        ab = _e191;
        let _e192 = (*l_10);
        param_137 = _e192;
        param_138 = 1f;
        param_139 = true;
        let _e193 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_137), (&param_138), (&param_139));
        f0_ = _e193;
        let _e194 = (*l_10);
        param_140 = _e194;
        param_141 = 0f;
        param_142 = true;
        let _e195 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_140), (&param_141), (&param_142));
        f90_ = _e195;
        let _e197 = (*l_10).kind;
        if (_e197 == 1i) {
            let _e200 = (*l_10).c0_;
            local_21 = _e200;
        } else {
            local_21 = vec3<f32>(1f, 1f, 1f);
        }
        let _e201 = local_21;
        tint_1 = _e201;
        let _e203 = (*l_10).alpha;
        param_143 = _e203;
        let _e204 = mxc_is_delta_u0028_vf2_u003b((&param_143));
        if _e204 {
            let _e205 = (*l_10);
            param_144 = _e205;
            let _e206 = mu_7;
            param_145 = _e206;
            param_146 = true;
            let _e207 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_144), (&param_145), (&param_146));
            let _e208 = tint_1;
            return (_e207 * _e208);
        }
        let _e210 = f0_;
        let _e212 = ab[0u];
        let _e214 = f90_;
        let _e216 = ab[1u];
        let _e219 = tint_1;
        let _e221 = (*ms);
        return clamp(((((_e210 * _e212) + (_e214 * _e216)) * _e219) * _e221), vec3(0f), vec3(1f));
    }
    let _e227 = (*l_10).kind;
    if (_e227 == 8i) {
        let _e230 = (*l_10).c0_;
        return _e230;
    }
    let _e232 = (*l_10).c0_;
    return _e232;
}

fn mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_11: ptr<function, MxcLobe>, woLocal: ptr<function, vec3<f32>>, ms_1: ptr<function, vec3<f32>>) -> f32 {
    var param_147: MxcLobe;
    var param_148: vec3<f32>;
    var param_149: vec3<f32>;
    var param_150: vec3<f32>;

    let _e120 = (*l_11).weight;
    if all((_e120 == vec3<f32>(0f, 0f, 0f))) {
        return 0f;
    }
    let _e124 = (*l_11).weight;
    let _e125 = (*l_11);
    param_147 = _e125;
    let _e126 = (*woLocal);
    param_148 = _e126;
    let _e127 = (*ms_1);
    param_149 = _e127;
    let _e128 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_147), (&param_148), (&param_149));
    param_150 = (_e124 * _e128);
    let _e130 = mxc_luminance_u0028_vf3_u003b((&param_150));
    return (max(_e130, 0f) + 0.0001f);
}

fn mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b(mu_8: ptr<function, f32>, alpha_12: ptr<function, f32>, eta_2: ptr<function, f32>) -> f32 {
    var param_151: f32;
    var param_152: f32;
    var param_153: f32;
    var param_154: f32;
    var param_155: f32;
    var param_156: f32;

    let _e121 = (*eta_2);
    if (_e121 >= 1f) {
        let _e123 = (*mu_8);
        param_151 = _e123;
        let _e124 = (*alpha_12);
        param_152 = _e124;
        let _e125 = (*eta_2);
        param_153 = _e125;
        let _e126 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_151), (&param_152), (&param_153));
        return _e126.y;
    }
    let _e128 = (*eta_2);
    let _e131 = (*mu_8);
    param_154 = _e131;
    let _e132 = (*alpha_12);
    param_155 = _e132;
    param_156 = (1f / max(_e128, 0.001f));
    let _e133 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_154), (&param_155), (&param_156));
    return _e133.z;
}

fn mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_12: ptr<function, MxcLobe>) -> bool {
    let _e114 = (*l_12).eta;
    return (abs((_e114 - 1f)) < 0.0001f);
}

fn mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_13: ptr<function, MxcLobe>, wo_12: ptr<function, vec3<f32>>) -> vec3<f32> {
    var microfacet: bool;
    var param_157: vec2<f32>;
    var alpha_13: f32;
    var param_158: MxcLobe;
    var e_3: f32;
    var param_159: MxcLobe;
    var param_160: bool;
    var param_161: f32;
    var param_162: f32;
    var param_163: f32;
    var k_3: vec3<f32>;
    var ab_1: vec2<f32>;
    var param_164: f32;
    var param_165: f32;
    var e_4: f32;
    var param_166: MxcLobe;
    var param_167: f32;
    var param_168: bool;
    var phi_1935_: bool;
    var phi_1942_: bool;
    var phi_1951_: bool;
    var phi_1967_: bool;
    var phi_1979_: bool;

    let _e133 = (*l_13).kind;
    let _e134 = (_e133 == 1i);
    phi_1935_ = _e134;
    if !(_e134) {
        let _e137 = (*l_13).kind;
        phi_1935_ = (_e137 == 2i);
    }
    let _e140 = phi_1935_;
    phi_1942_ = _e140;
    if !(_e140) {
        let _e143 = (*l_13).kind;
        phi_1942_ = (_e143 == 3i);
    }
    let _e146 = phi_1942_;
    microfacet = _e146;
    let _e147 = microfacet;
    let _e148 = !(_e147);
    phi_1951_ = _e148;
    if !(_e148) {
        let _e151 = (*l_13).alpha;
        param_157 = _e151;
        let _e152 = mxc_is_delta_u0028_vf2_u003b((&param_157));
        phi_1951_ = _e152;
    }
    let _e154 = phi_1951_;
    if _e154 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e157 = (*l_13).alpha[0u];
    let _e160 = (*l_13).alpha[1u];
    alpha_13 = sqrt((_e157 * _e160));
    let _e164 = (*l_13).kind;
    let _e165 = (_e164 == 1i);
    phi_1967_ = _e165;
    if _e165 {
        let _e166 = (*l_13);
        param_158 = _e166;
        let _e167 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_158));
        phi_1967_ = _e167;
    }
    let _e169 = phi_1967_;
    if _e169 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e171 = (*l_13).kind;
    let _e172 = (_e171 == 1i);
    phi_1979_ = _e172;
    if _e172 {
        let _e174 = (*l_13).mode;
        phi_1979_ = ((_e174 & 4i) == 0i);
    }
    let _e178 = phi_1979_;
    if _e178 {
        let _e180 = (*wo_12)[2u];
        let _e183 = (*wo_12)[2u];
        let _e185 = (*l_13);
        param_159 = _e185;
        param_160 = (_e183 >= 0f);
        let _e186 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_159), (&param_160));
        param_161 = abs(_e180);
        let _e187 = alpha_13;
        param_162 = _e187;
        param_163 = _e186;
        let _e188 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_161), (&param_162), (&param_163));
        e_3 = _e188;
        let _e189 = e_3;
        k_3 = vec3((1f / max(_e189, 0.05f)));
        let _e193 = k_3;
        return _e193;
    }
    let _e195 = (*wo_12)[2u];
    param_164 = max(_e195, 0f);
    let _e197 = alpha_13;
    param_165 = _e197;
    let _e198 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_164), (&param_165));
    ab_1 = _e198;
    let _e200 = ab_1[0u];
    let _e202 = ab_1[1u];
    e_4 = (_e200 + _e202);
    let _e204 = (*l_13);
    param_166 = _e204;
    param_167 = 1f;
    param_168 = true;
    let _e205 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_166), (&param_167), (&param_168));
    let _e206 = e_4;
    let _e209 = e_4;
    return (vec3(1f) + ((_e205 * (1f - _e206)) / vec3(max(_e209, 0.05f))));
}

fn mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b(c_8: ptr<function, MxcClosure>, wo_13: ptr<function, vec3<f32>>) {
    var k_4: i32;
    var l_14: MxcLobe;
    var o_4: vec3<f32>;
    var param_169: vec3<f32>;
    var param_170: vec3<f32>;
    var param_171: mat3x3<f32>;
    var param_172: vec3<f32>;
    var param_173: MxcLobe;
    var param_174: vec3<f32>;
    var param_175: MxcLobe;
    var param_176: vec3<f32>;
    var param_177: vec3<f32>;

    (*c_8).choiceTotal = 0f;
    k_4 = 0i;
    loop {
        let _e127 = k_4;
        let _e129 = (*c_8).count;
        if (_e127 < _e129) {
            let _e131 = k_4;
            let _e134 = (*c_8).lobes[_e131];
            l_14 = _e134;
            let _e135 = k_4;
            (*c_8).ms[_e135] = vec3<f32>(1f, 1f, 1f);
            let _e138 = k_4;
            (*c_8).choice[_e138] = 0f;
            let _e142 = l_14.weight;
            if all((_e142 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e146 = l_14.N;
            param_169 = _e146;
            let _e148 = l_14.T;
            param_170 = _e148;
            let _e149 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_169), (&param_170));
            param_171 = _e149;
            let _e150 = (*wo_13);
            param_172 = _e150;
            let _e151 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_171), (&param_172));
            o_4 = _e151;
            let _e152 = k_4;
            let _e153 = l_14;
            param_173 = _e153;
            let _e154 = o_4;
            param_174 = _e154;
            let _e155 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_173), (&param_174));
            (*c_8).ms[_e152] = _e155;
            let _e158 = k_4;
            let _e159 = k_4;
            let _e160 = l_14;
            param_175 = _e160;
            let _e161 = o_4;
            param_176 = _e161;
            let _e164 = (*c_8).ms[_e159];
            param_177 = _e164;
            let _e165 = mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_175), (&param_176), (&param_177));
            (*c_8).choice[_e158] = _e165;
            let _e168 = k_4;
            let _e171 = (*c_8).choice[_e168];
            let _e173 = (*c_8).choiceTotal;
            (*c_8).choiceTotal = (_e173 + _e171);
            continue;
        } else {
            break;
        }
        continuing {
            let _e176 = k_4;
            k_4 = (_e176 + 1i);
        }
    }
    return;
}

fn mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_15: ptr<function, MxcLobe>, wo_14: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_178: MxcLobe;
    var param_179: vec3<f32>;
    var param_180: MxcLobe;
    var param_181: vec3<f32>;
    var param_182: vec3<f32>;

    let _e119 = (*l_15);
    param_178 = _e119;
    let _e120 = (*wo_14);
    param_179 = _e120;
    let _e121 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_178), (&param_179));
    let _e122 = (*l_15);
    param_180 = _e122;
    let _e123 = (*wo_14);
    param_181 = _e123;
    param_182 = _e121;
    let _e124 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_180), (&param_181), (&param_182));
    return _e124;
}

fn mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_16: ptr<function, MxcLobe>, wo_15: ptr<function, vec3<f32>>) -> vec3<f32> {
    var white: MxcLobe;
    var param_183: MxcLobe;
    var param_184: vec3<f32>;
    var param_185: MxcLobe;
    var param_186: vec3<f32>;
    var phi_2186_: bool;

    let _e120 = (*l_16).kind;
    let _e121 = (_e120 == 9i);
    phi_2186_ = _e121;
    if !(_e121) {
        let _e124 = (*l_16).kind;
        phi_2186_ = (_e124 == 10i);
    }
    let _e127 = phi_2186_;
    if _e127 {
        let _e128 = (*l_16);
        white = _e128;
        white.c0_ = vec3<f32>(1f, 1f, 1f);
        let _e130 = white;
        param_183 = _e130;
        let _e131 = (*wo_15);
        param_184 = _e131;
        let _e132 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_183), (&param_184));
        return _e132;
    }
    let _e133 = (*l_16);
    param_185 = _e133;
    let _e134 = (*wo_15);
    param_186 = _e134;
    let _e135 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_185), (&param_186));
    return _e135;
}

fn mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b(g_1: ptr<function, MxcGeometry>, wo_16: ptr<function, vec3<f32>>, c_9: ptr<function, MxcClosure>) {
    var v5_: vec3<f32>;
    var v6_: vec3<f32>;
    var lobe0_: MxcLobe;
    var e1_: vec3<f32>;
    var param_187: vec3<f32>;
    var param_188: vec3<f32>;
    var param_189: mat3x3<f32>;
    var param_190: vec3<f32>;
    var param_191: MxcLobe;
    var param_192: vec3<f32>;
    var w2_: vec3<f32>;
    var lobe3_: MxcLobe;
    var param_193: MxcClosure;
    var param_194: vec3<f32>;

    let _e130 = (*g_1).N;
    v5_ = _e130;
    let _e132 = (*g_1).T;
    v6_ = _e132;
    (*c_9).emission = vec3<f32>(0f, 0f, 0f);
    (*c_9).transparency = vec3<f32>(0f, 0f, 0f);
    lobe0_.kind = 1i;
    lobe0_.mode = 1i;
    let _e137 = v5_;
    lobe0_.N = _e137;
    let _e139 = v6_;
    lobe0_.T = _e139;
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
    let _e152 = lobe0_.N;
    param_187 = _e152;
    let _e154 = lobe0_.T;
    param_188 = _e154;
    let _e155 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_187), (&param_188));
    param_189 = _e155;
    let _e156 = (*wo_16);
    param_190 = _e156;
    let _e157 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_189), (&param_190));
    let _e158 = lobe0_;
    param_191 = _e158;
    param_192 = _e157;
    let _e159 = mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_191), (&param_192));
    e1_ = _e159;
    let _e160 = e1_;
    w2_ = (vec3<f32>(1f, 1f, 1f) - _e160);
    lobe3_.kind = 5i;
    lobe3_.mode = 1i;
    let _e164 = v5_;
    lobe3_.N = _e164;
    let _e167 = (*g_1).T;
    lobe3_.T = _e167;
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
    let _e180 = lobe0_;
    (*c_9).lobes[0i] = _e180;
    let _e183 = w2_;
    lobe3_.weight = _e183;
    let _e185 = lobe3_;
    (*c_9).lobes[1i] = _e185;
    (*c_9).count = 2i;
    let _e189 = (*c_9);
    param_193 = _e189;
    let _e190 = (*wo_16);
    param_194 = _e190;
    mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b((&param_193), (&param_194));
    let _e191 = param_193;
    (*c_9) = _e191;
    return;
}

fn mxc_closure_seed_u0028_u1_u003b(seed_1: ptr<function, u32>) {
    return;
}

fn mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b(v_6: ptr<function, vec3<f32>>, fallback: ptr<function, vec3<f32>>) -> vec3<f32> {
    var l2_1: f32;
    var local_22: vec3<f32>;

    let _e116 = (*v_6);
    let _e117 = (*v_6);
    l2_1 = dot(_e116, _e117);
    let _e119 = l2_1;
    if (_e119 > 0.00000000000000000001f) {
        let _e121 = (*v_6);
        let _e122 = l2_1;
        local_22 = (_e121 * inverseSqrt(_e122));
    } else {
        let _e125 = (*fallback);
        local_22 = _e125;
    }
    let _e126 = local_22;
    return _e126;
}

fn main_1() {
    var g_2: MxcGeometry;
    var N_1: vec3<f32>;
    var param_195: vec3<f32>;
    var param_196: vec3<f32>;
    var handedness: f32;
    var frame_4: mat3x3<f32>;
    var param_197: vec3<f32>;
    var param_198: vec3<f32>;
    var param_199: vec3<f32>;
    var param_200: vec3<f32>;
    var objectFrame: mat3x3<f32>;
    var param_201: vec3<f32>;
    var param_202: vec3<f32>;
    var wo_17: vec3<f32>;
    var param_203: vec3<f32>;
    var param_204: vec3<f32>;
    var param_205: u32;
    var param_206: u32;
    var param_207: u32;
    var param_208: u32;
    var c_10: MxcClosure;
    var param_209: MxcGeometry;
    var param_210: vec3<f32>;
    var param_211: MxcClosure;
    var radiance: vec3<f32>;
    var lights: i32;
    var kinds: i32;
    var image: bool;
    var n_1: i32;
    var local_23: i32;
    var seed_2: u32;
    var param_212: u32;
    var param_213: u32;
    var param_214: u32;
    var pixel: u32;
    var param_215: u32;
    var param_216: u32;
    var shift: vec4<f32>;
    var param_217: u32;
    var param_218: u32;
    var param_219: u32;
    var param_220: u32;
    var sum: vec3<f32>;
    var b_3: i32;
    var batchLights: i32;
    var batchSamples: i32;
    var local_24: i32;
    var index: u32;
    var choice: vec4<f32>;
    var param_221: u32;
    var param_222: u32;
    var param_223: u32;
    var param_224: u32;
    var param_225: u32;
    var param_226: u32;
    var param_227: u32;
    var param_228: u32;
    var smp: MxcSample;
    var param_229: MxcClosure;
    var param_230: vec3<f32>;
    var param_231: vec3<f32>;
    var above_4: bool;
    var seen: vec3<f32>;
    var local_25: vec3<f32>;
    var local_26: vec3<f32>;
    var param_232: vec3<f32>;
    var param_233: vec3<f32>;
    var param_234: vec3<f32>;
    var w_1: f32;
    var local_27: f32;
    var param_235: vec3<f32>;
    var param_236: f32;
    var param_237: vec3<f32>;
    var param_238: f32;
    var param_239: f32;
    var m_5: vec3<f32>;
    var lightPdf: f32;
    var imageWi: vec3<f32>;
    var imageSeen: vec3<f32>;
    var v_7: vec4<f32>;
    var param_240: u32;
    var param_241: u32;
    var param_242: u32;
    var param_243: vec4<f32>;
    var param_244: f32;
    var param_245: vec3<f32>;
    var param_246: f32;
    var param_247: vec3<f32>;
    var j_2: i32;
    var wi_7: vec3<f32>;
    var incoming: vec3<f32>;
    var use_: bool;
    var strategy: i32;
    var local_28: i32;
    var light: vec4<f32>;
    var directional: bool;
    var param_248: vec3<f32>;
    var param_249: vec3<f32>;
    var d_8: vec3<f32>;
    var d2_: f32;
    var spot: vec4<f32>;
    var f_6: vec3<f32>;
    var pdf_2: f32;
    var param_250: MxcClosure;
    var param_251: vec3<f32>;
    var param_252: vec3<f32>;
    var param_253: bool;
    var param_254: f32;
    var w_2: f32;
    var local_29: f32;
    var param_255: vec3<f32>;
    var param_256: f32;
    var param_257: vec3<f32>;
    var param_258: f32;
    var param_259: f32;
    var w_3: f32;
    var param_260: vec3<f32>;
    var param_261: f32;
    var param_262: f32;
    var coverage: f32;
    var param_263: vec3<f32>;
    var phi_599_: bool;
    var phi_610_: bool;
    var phi_672_: bool;
    var phi_729_: bool;
    var phi_730_: bool;
    var phi_763_: bool;
    var phi_805_: bool;

    let _e233 = vPosition_1;
    g_2.P = _e233;
    let _e235 = vObjectPosition_1;
    g_2.Pobj = _e235;
    let _e237 = vNormal_1;
    param_195 = _e237;
    param_196 = vec3<f32>(0f, 0f, 1f);
    let _e238 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_195), (&param_196));
    N_1 = _e238;
    let _e239 = gl_FrontFacing_1;
    if !(_e239) {
        let _e241 = N_1;
        N_1 = -(_e241);
    }
    let _e244 = vTangent_1[3u];
    handedness = select(1f, -1f, (_e244 < 0f));
    let _e247 = N_1;
    param_197 = _e247;
    let _e248 = vTangent_1;
    param_198 = _e248.xyz;
    let _e250 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_197), (&param_198));
    frame_4 = _e250;
    let _e251 = N_1;
    g_2.N = _e251;
    let _e254 = frame_4[0];
    g_2.T = _e254;
    let _e257 = frame_4[1];
    let _e258 = handedness;
    g_2.B = (_e257 * _e258);
    let _e261 = vObjectNormal_1;
    param_199 = _e261;
    param_200 = vec3<f32>(0f, 0f, 1f);
    let _e262 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_199), (&param_200));
    g_2.Nobj = _e262;
    let _e265 = g_2.Nobj;
    param_201 = _e265;
    let _e266 = vObjectTangent_1;
    param_202 = _e266;
    let _e267 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_201), (&param_202));
    objectFrame = _e267;
    let _e269 = objectFrame[0];
    g_2.Tobj = _e269;
    let _e272 = objectFrame[1];
    let _e273 = handedness;
    g_2.Bobj = (_e272 * _e273);
    let _e276 = vUv_1;
    g_2.uv = _e276;
    g_2.color = vec4<f32>(1f, 1f, 1f, 1f);
    let _e280 = mxc_view.objectToWorld;
    g_2.objectToWorld = _e280;
    let _e283 = mxc_params.frame;
    g_2.frame = _e283;
    let _e286 = mxc_params.time;
    g_2.time = _e286;
    let _e289 = mxc_view.eye;
    let _e291 = vPosition_1;
    param_203 = (_e289.xyz - _e291);
    let _e293 = N_1;
    param_204 = _e293;
    let _e294 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_203), (&param_204));
    wo_17 = _e294;
    let _e296 = gl_FragCoord_1[0u];
    let _e299 = gl_FragCoord_1[1u];
    let _e303 = mxc_view.counts[2u];
    param_205 = (bitcast<u32>(_e303) + 7u);
    let _e306 = mxc_pcg_u0028_u1_u003b((&param_205));
    param_206 = (u32(_e299) + _e306);
    let _e308 = mxc_pcg_u0028_u1_u003b((&param_206));
    param_207 = (u32(_e296) ^ _e308);
    let _e310 = mxc_pcg_u0028_u1_u003b((&param_207));
    param_208 = _e310;
    mxc_closure_seed_u0028_u1_u003b((&param_208));
    let _e311 = g_2;
    param_209 = _e311;
    let _e312 = wo_17;
    param_210 = _e312;
    mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b((&param_209), (&param_210), (&param_211));
    let _e313 = param_211;
    c_10 = _e313;
    let _e315 = c_10.emission;
    let _e318 = mxc_view.environment[1u];
    radiance = (_e315 * _e318);
    let _e320 = mxc_light_count_u0028_();
    lights = _e320;
    let _e321 = mxc_light_kinds_u0028_();
    kinds = _e321;
    let _e322 = mxc_environment_code_u0028_();
    image = (_e322 == 3i);
    let _e324 = mxc_environment_code_u0028_();
    if (_e324 != 0i) {
        let _e328 = mxc_view.counts[3u];
        local_23 = max(_e328, 1i);
    } else {
        local_23 = 0i;
    }
    let _e330 = local_23;
    n_1 = _e330;
    let _e332 = gl_FragCoord_1[0u];
    let _e335 = gl_FragCoord_1[1u];
    let _e339 = mxc_view.counts[2u];
    param_212 = bitcast<u32>(_e339);
    let _e341 = mxc_pcg_u0028_u1_u003b((&param_212));
    param_213 = (u32(_e335) + _e341);
    let _e343 = mxc_pcg_u0028_u1_u003b((&param_213));
    param_214 = (u32(_e332) + _e343);
    let _e345 = mxc_pcg_u0028_u1_u003b((&param_214));
    seed_2 = _e345;
    let _e347 = gl_FragCoord_1[0u];
    let _e350 = gl_FragCoord_1[1u];
    param_215 = (u32(_e350) + 2654435769u);
    let _e353 = mxc_pcg_u0028_u1_u003b((&param_215));
    param_216 = (u32(_e347) ^ _e353);
    let _e355 = mxc_pcg_u0028_u1_u003b((&param_216));
    pixel = _e355;
    let _e356 = pixel;
    param_217 = _e356;
    let _e357 = mxc_uniform_u0028_u1_u003b((&param_217));
    let _e358 = param_217;
    pixel = _e358;
    let _e359 = pixel;
    param_218 = _e359;
    let _e360 = mxc_uniform_u0028_u1_u003b((&param_218));
    let _e361 = param_218;
    pixel = _e361;
    let _e362 = pixel;
    param_219 = _e362;
    let _e363 = mxc_uniform_u0028_u1_u003b((&param_219));
    let _e364 = param_219;
    pixel = _e364;
    let _e365 = pixel;
    param_220 = _e365;
    let _e366 = mxc_uniform_u0028_u1_u003b((&param_220));
    let _e367 = param_220;
    pixel = _e367;
    shift = vec4<f32>(_e357, _e360, _e363, _e366);
    sum = vec3<f32>(0f, 0f, 0f);
    b_3 = 0i;
    loop {
        let _e369 = b_3;
        let _e370 = n_1;
        let _e371 = lights;
        if (_e369 < max(_e370, select(0i, 1i, (_e371 > 0i)))) {
            let _e376 = b_3;
            let _e378 = lights;
            batchLights = select(0i, _e378, (_e376 == 0i));
            let _e380 = b_3;
            let _e381 = n_1;
            if (_e380 < _e381) {
                let _e383 = image;
                local_24 = (1i + select(0i, 1i, _e383));
            } else {
                local_24 = 0i;
            }
            let _e386 = local_24;
            batchSamples = _e386;
            let _e389 = mxc_view.counts[2u];
            let _e391 = n_1;
            let _e395 = b_3;
            index = ((bitcast<u32>(_e389) * bitcast<u32>(max(_e391, 1i))) + bitcast<u32>(_e395));
            let _e398 = index;
            param_221 = _e398;
            param_222 = 2u;
            let _e399 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_221), (&param_222));
            let _e400 = index;
            param_223 = _e400;
            param_224 = 3u;
            let _e401 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_223), (&param_224));
            let _e402 = index;
            param_225 = _e402;
            param_226 = 5u;
            let _e403 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_225), (&param_226));
            let _e404 = index;
            param_227 = _e404;
            param_228 = 7u;
            let _e405 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_227), (&param_228));
            let _e407 = shift;
            choice = fract((vec4<f32>(_e399, _e401, _e403, _e405) + _e407));
            smp.valid = false;
            smp.evaluate = false;
            smp.delta = false;
            smp.pdf = 0f;
            smp.weight = vec3<f32>(0f, 0f, 0f);
            let _e415 = N_1;
            smp.wi = _e415;
            let _e417 = n_1;
            if (_e417 > 0i) {
                let _e420 = choice[2u];
                let _e422 = choice[3u];
                let _e424 = choice[0u];
                let _e426 = c_10;
                param_229 = _e426;
                let _e427 = wo_17;
                param_230 = _e427;
                param_231 = vec3<f32>(_e420, _e422, _e424);
                let _e428 = mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b((&param_229), (&param_230), (&param_231));
                smp = _e428;
            }
            let _e430 = smp.wi;
            let _e431 = N_1;
            above_4 = (dot(_e430, _e431) > 0f);
            let _e435 = smp.valid;
            if _e435 {
                let _e436 = above_4;
                if _e436 {
                    let _e438 = smp.wi;
                    local_26 = _e438;
                } else {
                    let _e439 = wo_17;
                    param_232 = -(_e439);
                    let _e442 = smp.wi;
                    param_233 = _e442;
                    let _e443 = mxc_exit_direction_u0028_vf3_u003b_vf3_u003b((&param_232), (&param_233));
                    local_26 = _e443;
                }
                let _e444 = local_26;
                param_234 = _e444;
                let _e445 = mxc_environment_u0028_vf3_u003b((&param_234));
                local_25 = _e445;
            } else {
                local_25 = vec3<f32>(0f, 0f, 0f);
            }
            let _e446 = local_25;
            seen = _e446;
            let _e447 = b_3;
            let _e448 = n_1;
            let _e451 = smp.valid;
            let _e452 = ((_e447 < _e448) && _e451);
            phi_599_ = _e452;
            if _e452 {
                let _e454 = smp.evaluate;
                phi_599_ = !(_e454);
            }
            let _e457 = phi_599_;
            if _e457 {
                let _e458 = image;
                let _e459 = above_4;
                let _e460 = (_e458 && _e459);
                phi_610_ = _e460;
                if _e460 {
                    let _e462 = smp.delta;
                    phi_610_ = !(_e462);
                }
                let _e465 = phi_610_;
                if _e465 {
                    let _e467 = smp.wi;
                    param_235 = _e467;
                    let _e470 = mxc_view.environment[2u];
                    param_236 = _e470;
                    let _e471 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_235), (&param_236));
                    param_237 = _e471;
                    let _e472 = mxc_env_pdf_u0028_vf3_u003b((&param_237));
                    let _e474 = smp.pdf;
                    param_238 = _e474;
                    param_239 = _e472;
                    let _e475 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_238), (&param_239));
                    local_27 = _e475;
                } else {
                    local_27 = 1f;
                }
                let _e476 = local_27;
                w_1 = _e476;
                let _e477 = w_1;
                let _e479 = smp.weight;
                let _e481 = seen;
                let _e483 = sum;
                sum = (_e483 + ((_e479 * _e477) * _e481));
            }
            m_5 = vec3<f32>(0f, 0f, 0f);
            lightPdf = 0f;
            let _e485 = N_1;
            imageWi = _e485;
            imageSeen = vec3<f32>(0f, 0f, 0f);
            let _e486 = image;
            let _e487 = b_3;
            let _e488 = n_1;
            if (_e486 && (_e487 < _e488)) {
                let _e492 = choice[1u];
                let _e493 = seed_2;
                param_240 = _e493;
                let _e494 = mxc_uniform_u0028_u1_u003b((&param_240));
                let _e495 = param_240;
                seed_2 = _e495;
                let _e496 = seed_2;
                param_241 = _e496;
                let _e497 = mxc_uniform_u0028_u1_u003b((&param_241));
                let _e498 = param_241;
                seed_2 = _e498;
                let _e499 = seed_2;
                param_242 = _e499;
                let _e500 = mxc_uniform_u0028_u1_u003b((&param_242));
                let _e501 = param_242;
                seed_2 = _e501;
                v_7 = vec4<f32>(_e492, _e494, _e497, _e500);
                let _e503 = v_7;
                param_243 = _e503;
                let _e504 = mxc_env_sample_u0028_vf4_u003b_f1_u003b((&param_243), (&param_244));
                let _e505 = param_244;
                lightPdf = _e505;
                m_5 = _e504;
                let _e506 = m_5;
                param_245 = _e506;
                let _e509 = mxc_view.environment[2u];
                param_246 = _e509;
                let _e510 = mxc_env_to_world_u0028_vf3_u003b_f1_u003b((&param_245), (&param_246));
                imageWi = _e510;
                let _e511 = lightPdf;
                let _e512 = (_e511 > 0f);
                phi_672_ = _e512;
                if _e512 {
                    let _e513 = imageWi;
                    let _e514 = N_1;
                    phi_672_ = (dot(_e513, _e514) > 0f);
                }
                let _e518 = phi_672_;
                if _e518 {
                    let _e519 = imageWi;
                    param_247 = _e519;
                    let _e520 = mxc_environment_u0028_vf3_u003b((&param_247));
                    imageSeen = _e520;
                }
            }
            j_2 = 0i;
            loop {
                let _e521 = j_2;
                let _e522 = batchLights;
                let _e523 = batchSamples;
                if (_e521 < (_e522 + _e523)) {
                    let _e526 = N_1;
                    wi_7 = _e526;
                    incoming = vec3<f32>(0f, 0f, 0f);
                    use_ = true;
                    let _e527 = n_1;
                    let _e529 = j_2;
                    let _e530 = batchLights;
                    if ((_e527 == 0i) || (_e529 < _e530)) {
                        local_28 = 0i;
                    } else {
                        let _e533 = j_2;
                        let _e534 = batchLights;
                        local_28 = select(2i, 1i, (_e533 == ((_e534 + 1i) - 1i)));
                    }
                    let _e539 = local_28;
                    strategy = _e539;
                    let _e540 = strategy;
                    if (_e540 == 0i) {
                        let _e542 = j_2;
                        let _e545 = mxc_view.lightVector[_e542];
                        light = _e545;
                        let _e546 = j_2;
                        let _e549 = mxc_view.lightRadiance[_e546];
                        incoming = _e549.xyz;
                        let _e551 = kinds;
                        let _e552 = (_e551 == 1i);
                        phi_730_ = _e552;
                        if !(_e552) {
                            let _e554 = kinds;
                            let _e556 = ((_e554 & 1i) != 0i);
                            phi_729_ = _e556;
                            if _e556 {
                                let _e558 = light[3u];
                                phi_729_ = (_e558 == 0f);
                            }
                            let _e561 = phi_729_;
                            phi_730_ = _e561;
                        }
                        let _e563 = phi_730_;
                        directional = _e563;
                        let _e564 = directional;
                        if _e564 {
                            let _e565 = light;
                            param_248 = _e565.xyz;
                            let _e567 = N_1;
                            param_249 = _e567;
                            let _e568 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_248), (&param_249));
                            wi_7 = _e568;
                        } else {
                            let _e569 = light;
                            let _e571 = vPosition_1;
                            d_8 = (_e569.xyz - _e571);
                            let _e573 = d_8;
                            let _e574 = d_8;
                            d2_ = max(dot(_e573, _e574), 0.00000001f);
                            let _e577 = d_8;
                            let _e578 = d2_;
                            wi_7 = (_e577 * inverseSqrt(_e578));
                            let _e581 = d2_;
                            let _e582 = incoming;
                            incoming = (_e582 / vec3(_e581));
                            let _e585 = kinds;
                            let _e587 = ((_e585 & 4i) != 0i);
                            phi_763_ = _e587;
                            if _e587 {
                                let _e589 = light[3u];
                                phi_763_ = (_e589 == 2f);
                            }
                            let _e592 = phi_763_;
                            if _e592 {
                                let _e593 = j_2;
                                let _e596 = mxc_view.lightSpot[_e593];
                                spot = _e596;
                                let _e598 = spot[3u];
                                let _e599 = j_2;
                                let _e603 = mxc_view.lightRadiance[_e599][3u];
                                let _e604 = wi_7;
                                let _e606 = spot;
                                let _e610 = incoming;
                                incoming = (_e610 * smoothstep(_e598, _e603, dot(-(_e604), _e606.xyz)));
                            }
                        }
                    } else {
                        let _e612 = strategy;
                        if (_e612 == 1i) {
                            let _e615 = smp.wi;
                            wi_7 = _e615;
                            let _e616 = seen;
                            incoming = _e616;
                            let _e618 = smp.valid;
                            let _e620 = smp.evaluate;
                            use_ = (_e618 && _e620);
                        } else {
                            let _e622 = imageWi;
                            wi_7 = _e622;
                            let _e623 = imageSeen;
                            incoming = _e623;
                            let _e624 = lightPdf;
                            let _e625 = (_e624 > 0f);
                            phi_805_ = _e625;
                            if _e625 {
                                let _e626 = imageWi;
                                let _e627 = N_1;
                                phi_805_ = (dot(_e626, _e627) > 0f);
                            }
                            let _e631 = phi_805_;
                            use_ = _e631;
                        }
                    }
                    let _e632 = strategy;
                    let _e634 = c_10;
                    param_250 = _e634;
                    let _e635 = wo_17;
                    param_251 = _e635;
                    let _e636 = wi_7;
                    param_252 = _e636;
                    param_253 = (_e632 != 0i);
                    let _e637 = mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b((&param_250), (&param_251), (&param_252), (&param_253), (&param_254));
                    let _e638 = param_254;
                    pdf_2 = _e638;
                    f_6 = _e637;
                    let _e639 = strategy;
                    if (_e639 == 0i) {
                        let _e641 = f_6;
                        let _e642 = incoming;
                        let _e644 = radiance;
                        radiance = (_e644 + (_e641 * _e642));
                    } else {
                        let _e646 = strategy;
                        if (_e646 == 1i) {
                            let _e648 = use_;
                            let _e649 = pdf_2;
                            if (_e648 && (_e649 > 0f)) {
                                let _e652 = image;
                                let _e653 = above_4;
                                if (_e652 && _e653) {
                                    let _e655 = wi_7;
                                    param_255 = _e655;
                                    let _e658 = mxc_view.environment[2u];
                                    param_256 = _e658;
                                    let _e659 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_255), (&param_256));
                                    param_257 = _e659;
                                    let _e660 = mxc_env_pdf_u0028_vf3_u003b((&param_257));
                                    let _e661 = pdf_2;
                                    param_258 = _e661;
                                    param_259 = _e660;
                                    let _e662 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_258), (&param_259));
                                    local_29 = _e662;
                                } else {
                                    local_29 = 1f;
                                }
                                let _e663 = local_29;
                                w_2 = _e663;
                                let _e664 = w_2;
                                let _e665 = f_6;
                                let _e667 = pdf_2;
                                let _e670 = incoming;
                                let _e672 = sum;
                                sum = (_e672 + (((_e665 * _e664) / vec3(_e667)) * _e670));
                            }
                        } else {
                            let _e674 = use_;
                            if _e674 {
                                let _e675 = m_5;
                                param_260 = _e675;
                                let _e676 = mxc_env_pdf_u0028_vf3_u003b((&param_260));
                                param_261 = _e676;
                                let _e677 = pdf_2;
                                param_262 = _e677;
                                let _e678 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_261), (&param_262));
                                w_3 = _e678;
                                let _e679 = w_3;
                                let _e680 = f_6;
                                let _e682 = incoming;
                                let _e684 = lightPdf;
                                let _e687 = sum;
                                sum = (_e687 + (((_e680 * _e679) * _e682) / vec3(_e684)));
                            }
                        }
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e689 = j_2;
                    j_2 = (_e689 + 1i);
                }
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e691 = b_3;
            b_3 = (_e691 + 1i);
        }
    }
    let _e693 = sum;
    let _e694 = n_1;
    let _e699 = radiance;
    radiance = (_e699 + (_e693 / vec3(f32(max(_e694, 1i)))));
    let _e702 = c_10.transparency;
    param_263 = _e702;
    let _e703 = mxc_luminance_u0028_vf3_u003b((&param_263));
    coverage = (1f - clamp(_e703, 0f, 1f));
    let _e706 = radiance;
    let _e707 = coverage;
    outColor = vec4<f32>(_e706.x, _e706.y, _e706.z, _e707);
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
