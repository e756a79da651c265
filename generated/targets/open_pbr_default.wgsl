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
    let _e114 = (*c);
    return dot(_e114, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l: ptr<function, MxcLobe>) -> bool {
    return false;
}

fn mxc_mean_u0028_vf3_u003b(c_1: ptr<function, vec3<f32>>) -> f32 {
    let _e115 = (*c_1)[0u];
    let _e117 = (*c_1)[1u];
    let _e120 = (*c_1)[2u];
    return (((_e115 + _e117) + _e120) * 0.33333334f);
}

fn mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b(cosi: ptr<function, f32>, eta: ptr<function, f32>) -> f32 {
    var sin2t: f32;
    var cost: f32;
    var rs: f32;
    var rp: f32;

    let _e119 = (*eta);
    if (abs((_e119 - 1f)) < 0.000001f) {
        return 0f;
    }
    let _e123 = (*cosi);
    let _e124 = (*cosi);
    let _e127 = (*eta);
    let _e128 = (*eta);
    sin2t = ((1f - (_e123 * _e124)) / (_e127 * _e128));
    let _e131 = sin2t;
    if (_e131 >= 1f) {
        return 1f;
    }
    let _e133 = sin2t;
    cost = sqrt((1f - _e133));
    let _e136 = (*cosi);
    let _e137 = (*eta);
    let _e138 = cost;
    let _e141 = (*cosi);
    let _e142 = (*eta);
    let _e143 = cost;
    rs = ((_e136 - (_e137 * _e138)) / (_e141 + (_e142 * _e143)));
    let _e147 = (*eta);
    let _e148 = (*cosi);
    let _e150 = cost;
    let _e152 = (*eta);
    let _e153 = (*cosi);
    let _e155 = cost;
    rp = (((_e147 * _e148) - _e150) / ((_e152 * _e153) + _e155));
    let _e158 = rs;
    let _e159 = rs;
    let _e161 = rp;
    let _e162 = rp;
    return (0.5f * ((_e158 * _e159) + (_e161 * _e162)));
}

fn mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_1: ptr<function, MxcLobe>, above: ptr<function, bool>) -> f32 {
    var local: f32;

    let _e116 = (*above);
    if _e116 {
        let _e118 = (*l_1).eta;
        local = _e118;
    } else {
        let _e120 = (*l_1).eta;
        local = (1f / _e120);
    }
    let _e122 = local;
    return _e122;
}

fn mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b(l_2: ptr<function, MxcLobe>, cosh_: ptr<function, f32>, above_1: ptr<function, bool>) -> vec3<f32> {
    var f: vec3<f32>;
    var param: MxcLobe;
    var param_1: bool;
    var param_2: f32;
    var param_3: f32;

    f = vec3<f32>(1f, 1f, 1f);
    let _e122 = (*l_2).kind;
    if (_e122 == 1i) {
        let _e124 = (*l_2);
        param = _e124;
        let _e125 = (*above_1);
        param_1 = _e125;
        let _e126 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param), (&param_1));
        let _e127 = (*cosh_);
        param_2 = _e127;
        param_3 = _e126;
        let _e128 = mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b((&param_2), (&param_3));
        f = vec3(_e128);
    }
    let _e130 = f;
    return _e130;
}

fn mxc_rough_alpha_u0028_vf2_u003b(alpha: ptr<function, vec2<f32>>) -> vec2<f32> {
    let _e114 = (*alpha);
    return max(_e114, vec2<f32>(0.0001f, 0.0001f));
}

fn mxc_ggx_d_u0028_vf3_u003b_vf2_u003b(m: ptr<function, vec3<f32>>, alpha_1: ptr<function, vec2<f32>>) -> f32 {
    var param_4: vec2<f32>;
    var s: vec3<f32>;
    var d: f32;

    let _e119 = (*m)[2u];
    if (_e119 <= 0f) {
        return 0f;
    }
    let _e121 = (*alpha_1);
    param_4 = _e121;
    let _e122 = mxc_rough_alpha_u0028_vf2_u003b((&param_4));
    (*alpha_1) = _e122;
    let _e124 = (*m)[0u];
    let _e126 = (*alpha_1)[0u];
    let _e129 = (*m)[1u];
    let _e131 = (*alpha_1)[1u];
    let _e134 = (*m)[2u];
    s = vec3<f32>((_e124 / _e126), (_e129 / _e131), _e134);
    let _e136 = s;
    let _e137 = s;
    d = dot(_e136, _e137);
    let _e140 = (*alpha_1)[0u];
    let _e143 = (*alpha_1)[1u];
    let _e145 = d;
    let _e147 = d;
    return (1f / ((((3.1415927f * _e140) * _e143) * _e145) * _e147));
}

fn mxc_sqr_u0028_f1_u003b(x: ptr<function, f32>) -> f32 {
    let _e114 = (*x);
    let _e115 = (*x);
    return (_e114 * _e115);
}

fn mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b(v: ptr<function, vec3<f32>>, alpha_2: ptr<function, vec2<f32>>) -> f32 {
    var param_5: vec2<f32>;
    var z2_: f32;
    var a2_: f32;
    var param_6: f32;
    var param_7: f32;

    let _e120 = (*alpha_2);
    param_5 = _e120;
    let _e121 = mxc_rough_alpha_u0028_vf2_u003b((&param_5));
    (*alpha_2) = _e121;
    let _e123 = (*v)[2u];
    let _e125 = (*v)[2u];
    z2_ = (_e123 * _e125);
    let _e127 = z2_;
    if (_e127 <= 0f) {
        return 10000000000f;
    }
    let _e130 = (*alpha_2)[0u];
    let _e132 = (*v)[0u];
    param_6 = (_e130 * _e132);
    let _e134 = mxc_sqr_u0028_f1_u003b((&param_6));
    let _e136 = (*alpha_2)[1u];
    let _e138 = (*v)[1u];
    param_7 = (_e136 * _e138);
    let _e140 = mxc_sqr_u0028_f1_u003b((&param_7));
    let _e142 = z2_;
    a2_ = ((_e134 + _e140) / _e142);
    let _e144 = a2_;
    return (0.5f * (-1f + sqrt((1f + _e144))));
}

fn mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b(v_1: ptr<function, vec3<f32>>, alpha_3: ptr<function, vec2<f32>>) -> f32 {
    var param_8: vec3<f32>;
    var param_9: vec2<f32>;

    let _e117 = (*v_1);
    param_8 = _e117;
    let _e118 = (*alpha_3);
    param_9 = _e118;
    let _e119 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_8), (&param_9));
    return (1f / (1f + _e119));
}

fn mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo: ptr<function, vec3<f32>>, m_1: ptr<function, vec3<f32>>, alpha_4: ptr<function, vec2<f32>>) -> f32 {
    var param_10: vec3<f32>;
    var param_11: vec2<f32>;
    var param_12: vec3<f32>;
    var param_13: vec2<f32>;

    let _e121 = (*wo)[2u];
    if (_e121 <= 0f) {
        return 0f;
    }
    let _e123 = (*wo);
    param_10 = _e123;
    let _e124 = (*alpha_4);
    param_11 = _e124;
    let _e125 = mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b((&param_10), (&param_11));
    let _e126 = (*wo);
    let _e127 = (*m_1);
    let _e131 = (*m_1);
    param_12 = _e131;
    let _e132 = (*alpha_4);
    param_13 = _e132;
    let _e133 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_12), (&param_13));
    let _e136 = (*wo)[2u];
    return (((_e125 * max(dot(_e126, _e127), 0f)) * _e133) / _e136);
}

fn mxc_is_delta_u0028_vf2_u003b(alpha_5: ptr<function, vec2<f32>>) -> bool {
    let _e115 = (*alpha_5)[0u];
    let _e117 = (*alpha_5)[1u];
    return (max(_e115, _e117) < 0.0001f);
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
    var phi_2350_: bool;
    var phi_2431_: bool;

    let _e135 = (*l_3).kind;
    switch _e135 {
        case 2, 3, 1: {
            let _e149 = (*l_3).alpha;
            param_14 = _e149;
            let _e150 = mxc_is_delta_u0028_vf2_u003b((&param_14));
            if _e150 {
                return 0f;
            }
            let _e152 = (*wo_1)[2u];
            above_2 = (_e152 > 0f);
            let _e154 = above_2;
            if _e154 {
                let _e155 = (*wo_1);
                local_1 = _e155;
            } else {
                let _e156 = (*wo_1);
                local_1 = -(_e156);
            }
            let _e158 = local_1;
            o = _e158;
            let _e159 = above_2;
            if _e159 {
                let _e160 = (*wi);
                local_2 = _e160;
            } else {
                let _e161 = (*wi);
                local_2 = -(_e161);
            }
            let _e163 = local_2;
            i = _e163;
            let _e165 = i[2u];
            if (_e165 > 0f) {
                let _e167 = o;
                let _e168 = i;
                h = normalize((_e167 + _e168));
                let _e171 = o;
                param_15 = _e171;
                let _e172 = h;
                param_16 = _e172;
                let _e174 = (*l_3).alpha;
                param_17 = _e174;
                let _e175 = mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_15), (&param_16), (&param_17));
                let _e176 = o;
                let _e177 = h;
                p = (_e175 / (4f * max(dot(_e176, _e177), 0.000001f)));
                let _e183 = (*l_3).kind;
                if (_e183 == 2i) {
                    let _e185 = p;
                    return _e185;
                }
                let _e187 = (*l_3).mode;
                if ((_e187 & 1i) == 0i) {
                    return 0f;
                }
                let _e190 = o;
                let _e191 = h;
                let _e194 = (*l_3);
                param_18 = _e194;
                param_19 = max(dot(_e190, _e191), 0f);
                let _e195 = above_2;
                param_20 = _e195;
                let _e196 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_18), (&param_19), (&param_20));
                param_21 = _e196;
                let _e197 = mxc_mean_u0028_vf3_u003b((&param_21));
                fr = _e197;
                let _e198 = p;
                let _e199 = (*l_3);
                param_22 = _e199;
                let _e200 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_22));
                phi_2431_ = _e200;
                if _e200 {
                    let _e202 = (*l_3).mode;
                    phi_2431_ = ((_e202 & 1i) != 0i);
                }
                let _e206 = phi_2431_;
                let _e207 = fr;
                return (_e198 * select(1f, _e207, _e206));
            }
            return 0f;
        }
        default: {
            let _e137 = (*wo_1)[2u];
            let _e138 = (_e137 > 0f);
            phi_2350_ = _e138;
            if _e138 {
                let _e140 = (*wi)[2u];
                phi_2350_ = (_e140 > 0f);
            }
            let _e143 = phi_2350_;
            if _e143 {
                let _e145 = (*wi)[2u];
                local_3 = (_e145 * 0.31830987f);
            } else {
                local_3 = 0f;
            }
            let _e147 = local_3;
            return _e147;
        }
    }
}

fn mxc_safe_sqrt_u0028_f1_u003b(x_1: ptr<function, f32>) -> f32 {
    let _e114 = (*x_1);
    return sqrt(max(_e114, 0f));
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

    let _e123 = (*sigma);
    a = (1f / (1f + (0.2877934f * _e123)));
    let _e127 = (*mu);
    c_2 = clamp(_e127, 0f, 1f);
    let _e129 = c_2;
    let _e130 = c_2;
    param_23 = (1f - (_e129 * _e130));
    let _e133 = mxc_safe_sqrt_u0028_f1_u003b((&param_23));
    s_1 = _e133;
    let _e134 = c_2;
    theta = acos(_e134);
    let _e136 = c_2;
    if (_e136 > 0.0001f) {
        let _e138 = s_1;
        let _e139 = s_1;
        let _e141 = s_1;
        let _e144 = c_2;
        local_4 = ((1f - ((_e138 * _e139) * _e141)) / _e144);
    } else {
        let _e146 = c_2;
        local_4 = (1.5f * _e146);
    }
    let _e148 = local_4;
    tail = _e148;
    let _e149 = s_1;
    let _e150 = theta;
    let _e151 = s_1;
    let _e152 = c_2;
    let _e156 = s_1;
    let _e158 = tail;
    let _e161 = s_1;
    g = (((_e149 * (_e150 - (_e151 * _e152))) + ((0.6666667f * _e156) * _e158)) - (0.6666667f * _e161));
    let _e164 = a;
    let _e165 = (*sigma);
    let _e166 = a;
    let _e168 = g;
    return (_e164 + (((_e165 * _e166) * _e168) * 0.31830987f));
}

fn mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b(sigma_1: ptr<function, f32>, wo_2: ptr<function, vec3<f32>>, wi_1: ptr<function, vec3<f32>>) -> f32 {
    var a_1: f32;
    var s_2: f32;
    var t: f32;
    var local_5: f32;

    let _e120 = (*sigma_1);
    a_1 = (1f / (1f + (0.2877934f * _e120)));
    let _e124 = (*wi_1);
    let _e125 = (*wo_2);
    let _e128 = (*wi_1)[2u];
    let _e130 = (*wo_2)[2u];
    s_2 = (dot(_e124, _e125) - (_e128 * _e130));
    let _e133 = s_2;
    if (_e133 > 0f) {
        let _e136 = (*wi_1)[2u];
        let _e138 = (*wo_2)[2u];
        local_5 = max(max(_e136, _e138), 0.000001f);
    } else {
        local_5 = 1f;
    }
    let _e141 = local_5;
    t = _e141;
    let _e142 = a_1;
    let _e143 = (*sigma_1);
    let _e144 = a_1;
    let _e146 = s_2;
    let _e148 = t;
    return ((_e142 + (((_e143 * _e144) * _e146) / _e148)) * 0.31830987f);
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

    let _e128 = (*rho);
    let _e129 = (*sigma_2);
    param_24 = _e129;
    let _e130 = (*wo_3);
    param_25 = _e130;
    let _e131 = (*wi_2);
    param_26 = _e131;
    let _e132 = mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b((&param_24), (&param_25), (&param_26));
    f_1 = (_e128 * _e132);
    let _e134 = (*sigma_2);
    a_2 = (1f / (1f + (0.2877934f * _e134)));
    let _e138 = a_2;
    let _e139 = (*sigma_2);
    eavg = (_e138 * (1f + (0.07248821f * _e139)));
    let _e143 = eavg;
    if (_e143 < 0.999999f) {
        let _e145 = (*rho);
        let _e146 = (*rho);
        let _e148 = eavg;
        let _e150 = eavg;
        let _e154 = (*rho);
        let _e155 = eavg;
        rhoMs = ((((_e145 * _e146) * _e148) / vec3((1f - _e150))) / (vec3(1f) - (_e154 * (1f - _e155))));
        let _e161 = rhoMs;
        let _e162 = (*sigma_2);
        param_27 = _e162;
        let _e164 = (*wi_2)[2u];
        param_28 = _e164;
        let _e165 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_27), (&param_28));
        let _e168 = (*sigma_2);
        param_29 = _e168;
        let _e170 = (*wo_3)[2u];
        param_30 = _e170;
        let _e171 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_29), (&param_30));
        let _e175 = f_1;
        f_1 = (_e175 + (((_e161 * (1f - _e165)) * (1f - _e171)) * 0.31830987f));
    }
    let _e177 = f_1;
    return _e177;
}

fn mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo_4: ptr<function, vec3<f32>>, wi_3: ptr<function, vec3<f32>>, alpha_6: ptr<function, vec2<f32>>) -> f32 {
    var param_31: vec3<f32>;
    var param_32: vec2<f32>;
    var param_33: vec3<f32>;
    var param_34: vec2<f32>;

    let _e120 = (*wo_4);
    param_31 = _e120;
    let _e121 = (*alpha_6);
    param_32 = _e121;
    let _e122 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_31), (&param_32));
    let _e124 = (*wi_3);
    param_33 = _e124;
    let _e125 = (*alpha_6);
    param_34 = _e125;
    let _e126 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_33), (&param_34));
    return (1f / ((1f + _e122) + _e126));
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
    var phi_1697_: bool;
    var phi_1704_: bool;

    let _e128 = (*wo_5)[2u];
    let _e129 = (_e128 <= 0f);
    phi_1697_ = _e129;
    if !(_e129) {
        let _e132 = (*wi_4)[2u];
        phi_1697_ = (_e132 <= 0f);
    }
    let _e135 = phi_1697_;
    phi_1704_ = _e135;
    if !(_e135) {
        let _e138 = (*l_4).alpha;
        param_35 = _e138;
        let _e139 = mxc_is_delta_u0028_vf2_u003b((&param_35));
        phi_1704_ = _e139;
    }
    let _e141 = phi_1704_;
    if _e141 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e142 = (*wo_5);
    let _e143 = (*wi_4);
    h_1 = normalize((_e142 + _e143));
    let _e146 = (*wo_5);
    let _e147 = h_1;
    let _e150 = (*l_4);
    param_36 = _e150;
    param_37 = max(dot(_e146, _e147), 0f);
    param_38 = true;
    let _e151 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_36), (&param_37), (&param_38));
    f_2 = _e151;
    let _e153 = (*l_4).kind;
    if (_e153 == 1i) {
        let _e156 = (*l_4).c0_;
        let _e157 = f_2;
        f_2 = (_e157 * _e156);
    }
    let _e159 = f_2;
    let _e160 = h_1;
    param_39 = _e160;
    let _e162 = (*l_4).alpha;
    param_40 = _e162;
    let _e163 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_39), (&param_40));
    let _e165 = (*wo_5);
    param_41 = _e165;
    let _e166 = (*wi_4);
    param_42 = _e166;
    let _e168 = (*l_4).alpha;
    param_43 = _e168;
    let _e169 = mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_41), (&param_42), (&param_43));
    let _e172 = (*wo_5)[2u];
    return (((_e159 * _e163) * _e169) / vec3((4f * _e172)));
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
    var phi_2284_: bool;
    var phi_2299_: bool;

    let _e132 = (*l_5).kind;
    switch _e132 {
        case 1: {
            let _e134 = (*wo_6)[2u];
            let _e136 = (*wi_5)[2u];
            if ((_e134 * _e136) > 0f) {
                let _e140 = (*l_5).mode;
                if ((_e140 & 1i) == 0i) {
                    return vec3<f32>(0f, 0f, 0f);
                }
                let _e144 = (*wo_6)[2u];
                if (_e144 < 0f) {
                    let _e146 = (*l_5);
                    m_2 = _e146;
                    let _e148 = (*l_5).eta;
                    m_2.eta = (1f / _e148);
                    m_2.c0_ = vec3<f32>(1f, 1f, 1f);
                    let _e152 = (*wo_6);
                    let _e154 = (*wi_5);
                    let _e156 = m_2;
                    param_44 = _e156;
                    param_45 = -(_e152);
                    param_46 = -(_e154);
                    let _e157 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_44), (&param_45), (&param_46));
                    return _e157;
                }
                let _e158 = (*l_5);
                param_47 = _e158;
                let _e159 = (*wo_6);
                param_48 = _e159;
                let _e160 = (*wi_5);
                param_49 = _e160;
                let _e161 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_47), (&param_48), (&param_49));
                return _e161;
            }
            return vec3<f32>(0f, 0f, 0f);
        }
        case 3, 2: {
            let _e163 = (*l_5).kind;
            let _e164 = (_e163 == 3i);
            phi_2284_ = _e164;
            if _e164 {
                let _e166 = (*l_5).mode;
                phi_2284_ = ((_e166 & 1i) == 0i);
            }
            let _e170 = phi_2284_;
            if _e170 {
                return vec3<f32>(0f, 0f, 0f);
            }
            let _e171 = (*l_5);
            param_50 = _e171;
            let _e172 = (*wo_6);
            param_51 = _e172;
            let _e173 = (*wi_5);
            param_52 = _e173;
            let _e174 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_50), (&param_51), (&param_52));
            return _e174;
        }
        case 5: {
            let _e176 = (*wo_6)[2u];
            let _e177 = (_e176 > 0f);
            phi_2299_ = _e177;
            if _e177 {
                let _e179 = (*wi_5)[2u];
                phi_2299_ = (_e179 > 0f);
            }
            let _e182 = phi_2299_;
            if _e182 {
                let _e184 = (*l_5).c0_;
                param_53 = _e184;
                let _e186 = (*l_5).p0_;
                param_54 = _e186;
                let _e187 = (*wo_6);
                param_55 = _e187;
                let _e188 = (*wi_5);
                param_56 = _e188;
                let _e189 = mxc_eon_u0028_vf3_u003b_f1_u003b_vf3_u003b_vf3_u003b((&param_53), (&param_54), (&param_55), (&param_56));
                let _e191 = (*wi_5)[2u];
                local_6 = (_e189 * _e191);
            } else {
                local_6 = vec3<f32>(0f, 0f, 0f);
            }
            let _e193 = local_6;
            return _e193;
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
    let _e115 = (*v_2);
    let _e117 = (*frame)[0];
    let _e119 = (*v_2);
    let _e121 = (*frame)[1];
    let _e123 = (*v_2);
    let _e125 = (*frame)[2];
    return vec3<f32>(dot(_e115, _e117), dot(_e119, _e121), dot(_e123, _e125));
}

fn mxc_frame_u0028_vf3_u003b_vf3_u003b(N: ptr<function, vec3<f32>>, T: ptr<function, vec3<f32>>) -> mat3x3<f32> {
    var t_1: vec3<f32>;
    var l2_: f32;
    var s_3: f32;
    var a_3: f32;
    var b: f32;

    let _e120 = (*T);
    let _e121 = (*N);
    let _e122 = (*N);
    let _e123 = (*T);
    t_1 = (_e120 - (_e121 * dot(_e122, _e123)));
    let _e127 = t_1;
    let _e128 = t_1;
    l2_ = dot(_e127, _e128);
    let _e130 = l2_;
    if !((_e130 > 0.000000000001f)) {
        let _e134 = (*N)[2u];
        s_3 = select(-1f, 1f, (_e134 >= 0f));
        let _e137 = s_3;
        let _e139 = (*N)[2u];
        a_3 = (-1f / (_e137 + _e139));
        let _e143 = (*N)[0u];
        let _e145 = (*N)[1u];
        let _e147 = a_3;
        b = ((_e143 * _e145) * _e147);
        let _e149 = s_3;
        let _e151 = (*N)[0u];
        let _e154 = (*N)[0u];
        let _e156 = a_3;
        let _e159 = s_3;
        let _e160 = b;
        let _e162 = s_3;
        let _e165 = (*N)[0u];
        t_1 = vec3<f32>((1f + (((_e149 * _e151) * _e154) * _e156)), (_e159 * _e160), (-(_e162) * _e165));
    } else {
        let _e168 = l2_;
        let _e170 = t_1;
        t_1 = (_e170 * inverseSqrt(_e168));
    }
    let _e172 = t_1;
    let _e173 = (*N);
    let _e174 = t_1;
    let _e175 = cross(_e173, _e174);
    let _e176 = (*N);
    return mat3x3<f32>(vec3<f32>(_e172.x, _e172.y, _e172.z), vec3<f32>(_e175.x, _e175.y, _e175.z), vec3<f32>(_e176.x, _e176.y, _e176.z));
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
        let _e140 = k;
        let _e142 = (*c_3).count;
        if (_e140 < _e142) {
            let _e144 = k;
            let _e147 = (*c_3).lobes[_e144];
            l_7 = _e147;
            let _e149 = l_7.weight;
            if all((_e149 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e153 = l_7.N;
            param_57 = _e153;
            let _e155 = l_7.T;
            param_58 = _e155;
            let _e156 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_57), (&param_58));
            frame_1 = _e156;
            let _e157 = frame_1;
            param_59 = _e157;
            let _e158 = (*wo_7);
            param_60 = _e158;
            let _e159 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_59), (&param_60));
            o_1 = _e159;
            let _e160 = frame_1;
            param_61 = _e160;
            let _e161 = (*wi_6);
            param_62 = _e161;
            let _e162 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_61), (&param_62));
            i_1 = _e162;
            let _e164 = l_7.weight;
            let _e165 = k;
            let _e168 = (*c_3).ms[_e165];
            let _e171 = i_1[2u];
            let _e173 = l_7;
            param_63 = _e173;
            param_64 = abs(_e171);
            let _e174 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_63), (&param_64));
            let _e176 = l_7;
            param_65 = _e176;
            let _e177 = o_1;
            param_66 = _e177;
            let _e178 = i_1;
            param_67 = _e178;
            let _e179 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_65), (&param_66), (&param_67));
            let _e181 = f_3;
            f_3 = (_e181 + (((_e164 * _e168) * _e174) * _e179));
            let _e183 = (*wantPdf);
            if _e183 {
                let _e184 = k;
                let _e187 = (*c_3).choice[_e184];
                let _e188 = l_7;
                param_68 = _e188;
                let _e189 = o_1;
                param_69 = _e189;
                let _e190 = i_1;
                param_70 = _e190;
                let _e191 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_68), (&param_69), (&param_70));
                let _e193 = p_1;
                p_1 = (_e193 + (_e187 * _e191));
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e195 = k;
            k = (_e195 + 1i);
        }
    }
    let _e198 = (*c_3).choiceTotal;
    if (_e198 > 0f) {
        let _e200 = p_1;
        let _e202 = (*c_3).choiceTotal;
        local_7 = (_e200 / _e202);
    } else {
        local_7 = 0f;
    }
    let _e204 = local_7;
    (*pdf) = _e204;
    let _e205 = f_3;
    return _e205;
}

fn mxc_env_to_world_u0028_vf3_u003b_f1_u003b(m_3: ptr<function, vec3<f32>>, angle: ptr<function, f32>) -> vec3<f32> {
    var c_4: f32;
    var s_4: f32;

    let _e117 = (*angle);
    c_4 = cos(_e117);
    let _e119 = (*angle);
    s_4 = sin(_e119);
    let _e121 = c_4;
    let _e123 = (*m_3)[0u];
    let _e125 = s_4;
    let _e127 = (*m_3)[2u];
    let _e131 = (*m_3)[1u];
    let _e132 = s_4;
    let _e135 = (*m_3)[0u];
    let _e137 = c_4;
    let _e139 = (*m_3)[2u];
    return vec3<f32>(((_e121 * _e123) + (_e125 * _e127)), _e131, ((-(_e132) * _e135) + (_e137 * _e139)));
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

    let _e128 = unnamed.mxc_env_size;
    size = max(_e128.xy, vec2<u32>(1u, 1u));
    let _e132 = size[0u];
    let _e134 = size[1u];
    n = (_e132 * _e134);
    let _e137 = (*u)[0u];
    let _e138 = n;
    let _e142 = n;
    k_1 = min(u32((_e137 * f32(_e138))), (_e142 - 1u));
    let _e145 = k_1;
    let _e148 = unnamed.mxc_env_cells[_e145];
    cell = _e148;
    let _e150 = (*u)[1u];
    let _e152 = cell[0u];
    if (_e150 >= _e152) {
        let _e155 = cell[1u];
        let _e157 = n;
        k_1 = min(bitcast<u32>(_e155), (_e157 - 1u));
    }
    let _e160 = k_1;
    let _e164 = unnamed.mxc_env_cells[_e160][2u];
    (*pdf_1) = _e164;
    let _e165 = k_1;
    let _e167 = size[0u];
    i_2 = (_e165 % _e167);
    let _e169 = k_1;
    let _e171 = size[0u];
    j = (_e169 / _e171);
    let _e173 = i_2;
    let _e176 = (*u)[2u];
    let _e179 = size[0u];
    phi = (6.2831855f * (((f32(_e173) + _e176) / f32(_e179)) - 0.5f));
    let _e184 = j;
    let _e188 = size[1u];
    y0_ = cos(((3.1415927f * f32(_e184)) / f32(_e188)));
    let _e192 = j;
    let _e197 = size[1u];
    y1_ = cos(((3.1415927f * f32((_e192 + 1u))) / f32(_e197)));
    let _e201 = y0_;
    let _e202 = y1_;
    let _e204 = (*u)[3u];
    y = mix(_e201, _e202, _e204);
    let _e206 = y;
    let _e207 = y;
    param_71 = (1f - (_e206 * _e207));
    let _e210 = mxc_safe_sqrt_u0028_f1_u003b((&param_71));
    r = _e210;
    let _e211 = r;
    let _e212 = phi;
    let _e215 = y;
    let _e216 = r;
    let _e218 = phi;
    return vec3<f32>((_e211 * sin(_e212)), _e215, (-(_e216) * cos(_e218)));
}

fn mxc_power_heuristic_u0028_f1_u003b_f1_u003b(a_4: ptr<function, f32>, b_1: ptr<function, f32>) -> f32 {
    var a2_1: f32;
    var b2_: f32;
    var local_8: f32;

    let _e118 = (*a_4);
    let _e119 = (*a_4);
    a2_1 = (_e118 * _e119);
    let _e121 = (*b_1);
    let _e122 = (*b_1);
    b2_ = (_e121 * _e122);
    let _e124 = a2_1;
    let _e125 = b2_;
    if ((_e124 + _e125) > 0f) {
        let _e128 = a2_1;
        let _e129 = a2_1;
        let _e130 = b2_;
        local_8 = (_e128 / (_e129 + _e130));
    } else {
        local_8 = 0f;
    }
    let _e133 = local_8;
    return _e133;
}

fn mxc_env_uv_u0028_vf3_u003b(d_1: ptr<function, vec3<f32>>) -> vec2<f32> {
    var u_1: f32;
    var local_9: f32;
    var v_3: f32;

    let _e118 = (*d_1)[0u];
    let _e121 = (*d_1)[2u];
    if ((abs(_e118) + abs(_e121)) > 0.000000000001f) {
        let _e126 = (*d_1)[0u];
        let _e128 = (*d_1)[2u];
        local_9 = (0.5f + (atan2(_e126, -(_e128)) * 0.15915494f));
    } else {
        local_9 = 0.5f;
    }
    let _e133 = local_9;
    u_1 = _e133;
    let _e134 = (*d_1);
    let _e138 = (*d_1)[1u];
    v_3 = (atan2(length(_e134.xz), _e138) * 0.31830987f);
    let _e141 = u_1;
    let _e142 = v_3;
    return vec2<f32>(_e141, _e142);
}

fn mxc_env_cell_u0028_vf3_u003b(d_2: ptr<function, vec3<f32>>) -> u32 {
    var uv: vec2<f32>;
    var param_72: vec3<f32>;
    var size_1: vec2<u32>;
    var i_3: u32;
    var j_1: u32;

    let _e119 = (*d_2);
    param_72 = _e119;
    let _e120 = mxc_env_uv_u0028_vf3_u003b((&param_72));
    uv = _e120;
    let _e122 = unnamed.mxc_env_size;
    size_1 = max(_e122.xy, vec2<u32>(1u, 1u));
    let _e126 = uv[0u];
    let _e129 = size_1[0u];
    let _e134 = size_1[0u];
    i_3 = min(u32((max(_e126, 0f) * f32(_e129))), (_e134 - 1u));
    let _e138 = uv[1u];
    let _e141 = size_1[1u];
    let _e146 = size_1[1u];
    j_1 = min(u32((max(_e138, 0f) * f32(_e141))), (_e146 - 1u));
    let _e149 = j_1;
    let _e151 = size_1[0u];
    let _e153 = i_3;
    return ((_e149 * _e151) + _e153);
}

fn mxc_env_pdf_u0028_vf3_u003b(d_3: ptr<function, vec3<f32>>) -> f32 {
    var param_73: vec3<f32>;

    let _e115 = (*d_3);
    param_73 = _e115;
    let _e116 = mxc_env_cell_u0028_vf3_u003b((&param_73));
    let _e120 = unnamed.mxc_env_cells[_e116][2u];
    return _e120;
}

fn mxc_env_to_map_u0028_vf3_u003b_f1_u003b(w: ptr<function, vec3<f32>>, angle_1: ptr<function, f32>) -> vec3<f32> {
    var c_5: f32;
    var s_5: f32;

    let _e117 = (*angle_1);
    c_5 = cos(_e117);
    let _e119 = (*angle_1);
    s_5 = sin(_e119);
    let _e121 = c_5;
    let _e123 = (*w)[0u];
    let _e125 = s_5;
    let _e127 = (*w)[2u];
    let _e131 = (*w)[1u];
    let _e132 = s_5;
    let _e134 = (*w)[0u];
    let _e136 = c_5;
    let _e138 = (*w)[2u];
    return vec3<f32>(((_e121 * _e123) - (_e125 * _e127)), _e131, ((_e132 * _e134) + (_e136 * _e138)));
}

fn mxc_env_lookup_u0028_vf3_u003b(d_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_74: vec3<f32>;

    let _e115 = (*d_4);
    param_74 = _e115;
    let _e116 = mxc_env_uv_u0028_vf3_u003b((&param_74));
    let _e117 = textureSampleLevel(mxc_env_radiance_texture, mxc_env_radiance_sampler, _e116, 0f);
    return _e117.xyz;
}

fn mxc_sky_u0028_vf3_u003b(d_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var y_1: f32;
    var horizon: vec3<f32>;
    var zenith: vec3<f32>;
    var ground: vec3<f32>;

    let _e119 = (*d_5)[1u];
    y_1 = clamp(_e119, -1f, 1f);
    horizon = vec3<f32>(1f, 0.96f, 0.9f);
    zenith = vec3<f32>(0.3f, 0.5f, 0.95f);
    ground = vec3<f32>(0.16f, 0.145f, 0.13f);
    let _e121 = y_1;
    if (_e121 >= 0f) {
        let _e123 = horizon;
        let _e124 = zenith;
        let _e125 = y_1;
        return mix(_e123, _e124, vec3(sqrt(_e125)));
    }
    let _e129 = horizon;
    let _e130 = ground;
    let _e131 = y_1;
    return mix(_e129, _e130, vec3(sqrt(-(_e131))));
}

fn mxc_environment_code_u0028_() -> i32 {
    var local_10: i32;

    if false {
        local_10 = MXC_ENVIRONMENT;
    } else {
        let _e116 = mxc_view.counts[1u];
        local_10 = _e116;
    }
    let _e117 = local_10;
    return _e117;
}

fn mxc_environment_u0028_vf3_u003b(d_6: ptr<function, vec3<f32>>) -> vec3<f32> {
    var code: i32;
    var param_75: vec3<f32>;
    var param_76: vec3<f32>;
    var param_77: f32;
    var param_78: vec3<f32>;

    let _e119 = mxc_environment_code_u0028_();
    code = _e119;
    let _e120 = code;
    if (_e120 == 1i) {
        let _e124 = mxc_view.environment[0u];
        return vec3(_e124);
    }
    let _e126 = code;
    if (_e126 == 2i) {
        let _e130 = mxc_view.environment[0u];
        let _e131 = (*d_6);
        param_75 = _e131;
        let _e132 = mxc_sky_u0028_vf3_u003b((&param_75));
        return (_e132 * _e130);
    }
    let _e134 = code;
    if (_e134 == 3i) {
        let _e138 = mxc_view.environment[0u];
        let _e139 = (*d_6);
        param_76 = _e139;
        let _e142 = mxc_view.environment[2u];
        param_77 = _e142;
        let _e143 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_76), (&param_77));
        param_78 = _e143;
        let _e144 = mxc_env_lookup_u0028_vf3_u003b((&param_78));
        return (_e144 * _e138);
    }
    return vec3<f32>(0f, 0f, 0f);
}

fn mxc_exit_direction_u0028_vf3_u003b_vf3_u003b(d_7: ptr<function, vec3<f32>>, t_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var axis: vec3<f32>;
    var s_6: f32;
    var c_6: f32;

    let _e118 = (*d_7);
    let _e119 = (*t_2);
    axis = cross(_e118, _e119);
    let _e121 = axis;
    s_6 = length(_e121);
    let _e123 = s_6;
    if (_e123 < 0.000001f) {
        let _e125 = (*t_2);
        return _e125;
    }
    let _e126 = s_6;
    let _e127 = axis;
    axis = (_e127 / vec3(_e126));
    let _e130 = (*d_7);
    let _e131 = (*t_2);
    c_6 = dot(_e130, _e131);
    let _e133 = (*t_2);
    let _e134 = c_6;
    let _e136 = axis;
    let _e137 = (*t_2);
    let _e139 = s_6;
    let _e142 = axis;
    let _e143 = axis;
    let _e144 = (*t_2);
    let _e147 = c_6;
    return (((_e133 * _e134) + (cross(_e136, _e137) * _e139)) + ((_e142 * dot(_e143, _e144)) * (1f - _e147)));
}

fn mxc_to_world_u0028_mf33_u003b_vf3_u003b(frame_2: ptr<function, mat3x3<f32>>, v_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e116 = (*frame_2)[0];
    let _e118 = (*v_4)[0u];
    let _e121 = (*frame_2)[1];
    let _e123 = (*v_4)[1u];
    let _e127 = (*frame_2)[2];
    let _e129 = (*v_4)[2u];
    return (((_e116 * _e118) + (_e121 * _e123)) + (_e127 * _e129));
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

    let _e130 = (*alpha_7);
    param_79 = _e130;
    let _e131 = mxc_rough_alpha_u0028_vf2_u003b((&param_79));
    (*alpha_7) = _e131;
    let _e133 = (*alpha_7)[0u];
    let _e135 = (*wo_8)[0u];
    let _e138 = (*alpha_7)[1u];
    let _e140 = (*wo_8)[1u];
    let _e143 = (*wo_8)[2u];
    vh = normalize(vec3<f32>((_e133 * _e135), (_e138 * _e140), _e143));
    let _e147 = vh[0u];
    let _e149 = vh[0u];
    let _e152 = vh[1u];
    let _e154 = vh[1u];
    lensq = ((_e147 * _e149) + (_e152 * _e154));
    let _e157 = lensq;
    if (_e157 > 0f) {
        let _e160 = vh[1u];
        let _e163 = vh[0u];
        let _e165 = lensq;
        local_11 = (vec3<f32>(-(_e160), _e163, 0f) * inverseSqrt(_e165));
    } else {
        local_11 = vec3<f32>(1f, 0f, 0f);
    }
    let _e168 = local_11;
    t1_ = _e168;
    let _e169 = vh;
    let _e170 = t1_;
    t2_ = cross(_e169, _e170);
    let _e173 = (*u_2)[0u];
    r_1 = sqrt(_e173);
    let _e176 = (*u_2)[1u];
    phi_1 = (6.2831855f * _e176);
    let _e178 = r_1;
    let _e179 = phi_1;
    p1_ = (_e178 * cos(_e179));
    let _e182 = r_1;
    let _e183 = phi_1;
    p2_ = (_e182 * sin(_e183));
    let _e187 = vh[2u];
    s_7 = (0.5f * (1f + _e187));
    let _e190 = s_7;
    let _e192 = p1_;
    let _e193 = p1_;
    param_80 = (1f - (_e192 * _e193));
    let _e196 = mxc_safe_sqrt_u0028_f1_u003b((&param_80));
    let _e198 = s_7;
    let _e199 = p2_;
    p2_ = (((1f - _e190) * _e196) + (_e198 * _e199));
    let _e202 = p1_;
    let _e203 = t1_;
    let _e205 = p2_;
    let _e206 = t2_;
    let _e209 = p1_;
    let _e210 = p1_;
    let _e213 = p2_;
    let _e214 = p2_;
    param_81 = ((1f - (_e209 * _e210)) - (_e213 * _e214));
    let _e217 = mxc_safe_sqrt_u0028_f1_u003b((&param_81));
    let _e218 = vh;
    nh = (((_e203 * _e202) + (_e206 * _e205)) + (_e218 * _e217));
    let _e222 = (*alpha_7)[0u];
    let _e224 = nh[0u];
    let _e227 = (*alpha_7)[1u];
    let _e229 = nh[1u];
    let _e232 = nh[2u];
    return normalize(vec3<f32>((_e222 * _e224), (_e227 * _e229), max(_e232, 0f)));
}

fn mxc_sample_cosine_u0028_vf2_u003b(u_3: ptr<function, vec2<f32>>) -> vec3<f32> {
    var r_2: f32;
    var phi_2: f32;
    var param_82: f32;

    let _e118 = (*u_3)[0u];
    r_2 = sqrt(_e118);
    let _e121 = (*u_3)[1u];
    phi_2 = (6.2831855f * _e121);
    let _e123 = r_2;
    let _e124 = phi_2;
    let _e127 = r_2;
    let _e128 = phi_2;
    let _e132 = (*u_3)[0u];
    param_82 = (1f - _e132);
    let _e134 = mxc_safe_sqrt_u0028_f1_u003b((&param_82));
    return vec3<f32>((_e123 * cos(_e124)), (_e127 * sin(_e128)), _e134);
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
    var phi_2562_: bool;
    var phi_2567_: bool;
    var phi_2578_: bool;

    s_8.valid = false;
    s_8.delta = false;
    s_8.pdf = 0f;
    s_8.value = vec3<f32>(0f, 0f, 0f);
    s_8.wi = vec3<f32>(0f, 0f, 1f);
    let _e164 = (*l_8).kind;
    switch _e164 {
        case 2, 3, 1: {
            let _e191 = (*wo_9)[2u];
            above_3 = (_e191 > 0f);
            let _e193 = above_3;
            if _e193 {
                let _e194 = (*wo_9);
                local_12 = _e194;
            } else {
                let _e195 = (*wo_9);
                local_12 = -(_e195);
            }
            let _e197 = local_12;
            o_2 = _e197;
            let _e199 = o_2[2u];
            if (_e199 <= 0f) {
                let _e201 = s_8;
                return _e201;
            }
            let _e203 = (*l_8).alpha;
            param_83 = _e203;
            let _e204 = mxc_is_delta_u0028_vf2_u003b((&param_83));
            delta = _e204;
            let _e205 = delta;
            if _e205 {
                local_13 = vec3<f32>(0f, 0f, 1f);
            } else {
                let _e206 = o_2;
                param_84 = _e206;
                let _e208 = (*l_8).alpha;
                param_85 = _e208;
                let _e209 = (*u_4);
                param_86 = _e209.xy;
                let _e211 = mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b((&param_84), (&param_85), (&param_86));
                local_13 = _e211;
            }
            let _e212 = local_13;
            m_4 = _e212;
            let _e213 = o_2;
            let _e214 = m_4;
            hm = dot(_e213, _e214);
            let _e217 = (*l_8).kind;
            let _e218 = (_e217 == 1i);
            phi_2562_ = _e218;
            if !(_e218) {
                let _e221 = (*l_8).kind;
                phi_2562_ = (_e221 == 3i);
            }
            let _e224 = phi_2562_;
            phi_2567_ = _e224;
            if _e224 {
                let _e225 = (*l_8);
                param_87 = _e225;
                let _e226 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_87));
                phi_2567_ = _e226;
            }
            let _e228 = phi_2567_;
            transmits = _e228;
            let _e230 = (*l_8).kind;
            let _e231 = (_e230 == 2i);
            phi_2578_ = _e231;
            if !(_e231) {
                let _e234 = (*l_8).mode;
                phi_2578_ = ((_e234 & 1i) != 0i);
            }
            let _e238 = phi_2578_;
            reflects = _e238;
            let _e239 = hm;
            let _e241 = (*l_8);
            param_88 = _e241;
            param_89 = max(_e239, 0f);
            let _e242 = above_3;
            param_90 = _e242;
            let _e243 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_88), (&param_89), (&param_90));
            f_4 = _e243;
            let _e244 = transmits;
            if _e244 {
                let _e245 = f_4;
                param_91 = _e245;
                let _e246 = mxc_mean_u0028_vf3_u003b((&param_91));
                local_14 = _e246;
            } else {
                local_14 = 1f;
            }
            let _e247 = local_14;
            fr_1 = _e247;
            let _e248 = transmits;
            if _e248 {
                let _e249 = reflects;
                let _e250 = fr_1;
                local_15 = select(0f, _e250, _e249);
            } else {
                local_15 = 1f;
            }
            let _e252 = local_15;
            pReflect = _e252;
            let _e254 = (*u_4)[2u];
            let _e255 = pReflect;
            if (_e254 < _e255) {
                let _e257 = o_2;
                let _e259 = m_4;
                i_4 = reflect(-(_e257), _e259);
                let _e262 = i_4[2u];
                if (_e262 <= 0f) {
                    let _e264 = s_8;
                    return _e264;
                }
                let _e265 = above_3;
                if _e265 {
                    let _e266 = i_4;
                    local_16 = _e266;
                } else {
                    let _e267 = i_4;
                    local_16 = -(_e267);
                }
                let _e269 = local_16;
                s_8.wi = _e269;
                let _e271 = delta;
                s_8.delta = _e271;
                let _e273 = delta;
                if _e273 {
                    let _e275 = (*l_8).kind;
                    if (_e275 == 1i) {
                        let _e277 = above_3;
                        if _e277 {
                            let _e279 = (*l_8).c0_;
                            local_18 = _e279;
                        } else {
                            local_18 = vec3<f32>(1f, 1f, 1f);
                        }
                        let _e280 = local_18;
                        local_17 = _e280;
                    } else {
                        local_17 = vec3<f32>(1f, 1f, 1f);
                    }
                    let _e281 = local_17;
                    tint = _e281;
                    let _e282 = f_4;
                    let _e283 = tint;
                    s_8.value = (_e282 * _e283);
                    let _e286 = pReflect;
                    s_8.pdf = _e286;
                } else {
                    let _e288 = (*l_8);
                    param_92 = _e288;
                    let _e289 = (*wo_9);
                    param_93 = _e289;
                    let _e291 = s_8.wi;
                    param_94 = _e291;
                    let _e292 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_92), (&param_93), (&param_94));
                    s_8.value = _e292;
                    let _e294 = (*l_8);
                    param_95 = _e294;
                    let _e295 = (*wo_9);
                    param_96 = _e295;
                    let _e297 = s_8.wi;
                    param_97 = _e297;
                    let _e298 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_95), (&param_96), (&param_97));
                    s_8.pdf = _e298;
                }
                let _e301 = s_8.pdf;
                s_8.valid = (_e301 > 0f);
                let _e304 = s_8;
                return _e304;
            }
            let _e305 = s_8;
            return _e305;
        }
        default: {
            let _e166 = (*wo_9)[2u];
            if (_e166 <= 0f) {
                let _e168 = s_8;
                return _e168;
            }
            let _e169 = (*u_4);
            param_98 = _e169.xy;
            let _e171 = mxc_sample_cosine_u0028_vf2_u003b((&param_98));
            s_8.wi = _e171;
            let _e173 = (*l_8);
            param_99 = _e173;
            let _e174 = (*wo_9);
            param_100 = _e174;
            let _e176 = s_8.wi;
            param_101 = _e176;
            let _e177 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_99), (&param_100), (&param_101));
            s_8.value = _e177;
            let _e179 = (*l_8);
            param_102 = _e179;
            let _e180 = (*wo_9);
            param_103 = _e180;
            let _e182 = s_8.wi;
            param_104 = _e182;
            let _e183 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_102), (&param_103), (&param_104));
            s_8.pdf = _e183;
            let _e186 = s_8.pdf;
            s_8.valid = (_e186 > 0f);
            let _e189 = s_8;
            return _e189;
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
    let _e147 = (*wo_10);
    s_9.wi = _e147;
    let _e150 = (*c_7).choiceTotal;
    total = _e150;
    let _e152 = (*c_7).count;
    let _e154 = total;
    if ((_e152 == 0i) || (_e154 <= 0f)) {
        let _e157 = s_9;
        return _e157;
    }
    let _e159 = (*u_5)[2u];
    let _e160 = total;
    x_2 = (_e159 * _e160);
    chosen = -1i;
    before = 0f;
    p_2 = 0f;
    lastBefore = 0f;
    last = -1i;
    k_2 = 0i;
    loop {
        let _e162 = k_2;
        let _e164 = (*c_7).count;
        if (_e162 < _e164) {
            let _e166 = k_2;
            let _e169 = (*c_7).choice[_e166];
            pk = _e169;
            let _e170 = pk;
            if (_e170 <= 0f) {
                continue;
            }
            let _e172 = x_2;
            let _e173 = before;
            let _e174 = pk;
            if (_e172 < (_e173 + _e174)) {
                let _e177 = k_2;
                chosen = _e177;
                let _e178 = pk;
                p_2 = _e178;
                break;
            }
            let _e179 = k_2;
            last = _e179;
            let _e180 = before;
            lastBefore = _e180;
            let _e181 = pk;
            let _e182 = before;
            before = (_e182 + _e181);
            continue;
        } else {
            break;
        }
        continuing {
            let _e184 = k_2;
            k_2 = (_e184 + 1i);
        }
    }
    let _e186 = chosen;
    if (_e186 < 0i) {
        let _e188 = last;
        chosen = max(_e188, 0i);
        let _e190 = chosen;
        let _e193 = (*c_7).choice[_e190];
        p_2 = _e193;
        let _e194 = lastBefore;
        before = _e194;
    }
    let _e195 = p_2;
    if (_e195 <= 0f) {
        let _e197 = s_9;
        return _e197;
    }
    let _e198 = x_2;
    let _e199 = before;
    let _e201 = p_2;
    uz = clamp(((_e198 - _e199) / _e201), 0f, 0.99999994f);
    let _e204 = chosen;
    let _e207 = (*c_7).lobes[_e204];
    l_9 = _e207;
    let _e209 = l_9.N;
    param_105 = _e209;
    let _e211 = l_9.T;
    param_106 = _e211;
    let _e212 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_105), (&param_106));
    frame_3 = _e212;
    let _e213 = frame_3;
    param_107 = _e213;
    let _e214 = (*wo_10);
    param_108 = _e214;
    let _e215 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_107), (&param_108));
    o_3 = _e215;
    let _e216 = (*u_5);
    let _e217 = _e216.xy;
    let _e218 = uz;
    let _e222 = l_9;
    param_109 = _e222;
    let _e223 = o_3;
    param_110 = _e223;
    param_111 = vec3<f32>(_e217.x, _e217.y, _e218);
    let _e224 = mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_109), (&param_110), (&param_111));
    ls = _e224;
    let _e226 = ls.valid;
    if !(_e226) {
        let _e228 = s_9;
        return _e228;
    }
    let _e229 = frame_3;
    param_112 = _e229;
    let _e231 = ls.wi;
    param_113 = _e231;
    let _e232 = mxc_to_world_u0028_mf33_u003b_vf3_u003b((&param_112), (&param_113));
    s_9.wi = _e232;
    let _e235 = ls.delta;
    if _e235 {
        s_9.delta = true;
        let _e238 = ls.pdf;
        let _e239 = p_2;
        let _e241 = total;
        s_9.pdf = ((_e238 * _e239) / _e241);
        let _e245 = l_9.weight;
        let _e246 = chosen;
        let _e249 = (*c_7).ms[_e246];
        let _e253 = ls.wi[2u];
        let _e255 = l_9;
        param_114 = _e255;
        param_115 = abs(_e253);
        let _e256 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_114), (&param_115));
        let _e259 = ls.value;
        let _e262 = s_9.pdf;
        s_9.weight = ((((_e245 * _e249) * _e256) * _e259) / vec3(_e262));
        let _e267 = s_9.pdf;
        s_9.valid = (_e267 > 0f);
        let _e270 = s_9;
        return _e270;
    }
    s_9.evaluate = true;
    s_9.valid = true;
    let _e273 = s_9;
    return _e273;
}

fn mxc_radical_inverse_u0028_u1_u003b_u1_u003b(i_5: ptr<function, u32>, base: ptr<function, u32>) -> f32 {
    var inv: f32;
    var f_5: f32;
    var r_3: f32;

    let _e118 = (*base);
    if (_e118 == 2u) {
        let _e120 = (*i_5);
        return (f32((reverseBits(_e120) >> bitcast<u32>(8i))) * 0.000000059604645f);
    }
    let _e126 = (*base);
    inv = (1f / f32(_e126));
    let _e129 = inv;
    f_5 = _e129;
    r_3 = 0f;
    loop {
        let _e130 = (*i_5);
        if (_e130 > 0u) {
            let _e132 = f_5;
            let _e133 = (*i_5);
            let _e134 = (*base);
            let _e138 = r_3;
            r_3 = (_e138 + (_e132 * f32((_e133 % _e134))));
            let _e140 = inv;
            let _e141 = f_5;
            f_5 = (_e141 * _e140);
            continue;
        } else {
            break;
        }
        continuing {
            let _e143 = (*base);
            let _e144 = (*i_5);
            (*i_5) = (_e144 / _e143);
        }
    }
    let _e146 = r_3;
    return min(_e146, 0.99999994f);
}

fn mxc_pcg_u0028_u1_u003b(v_5: ptr<function, u32>) -> u32 {
    var state: u32;
    var word: u32;

    let _e116 = (*v_5);
    state = ((_e116 * 747796405u) + 2891336453u);
    let _e119 = state;
    let _e120 = state;
    let _e126 = state;
    word = (((_e119 >> bitcast<u32>(((_e120 >> bitcast<u32>(28u)) + 4u))) ^ _e126) * 277803737u);
    let _e129 = word;
    let _e132 = word;
    return ((_e129 >> bitcast<u32>(22u)) ^ _e132);
}

fn mxc_uniform_u0028_u1_u003b(seed: ptr<function, u32>) -> f32 {
    var param_116: u32;

    let _e115 = (*seed);
    param_116 = _e115;
    let _e116 = mxc_pcg_u0028_u1_u003b((&param_116));
    (*seed) = _e116;
    let _e117 = (*seed);
    return (f32((_e117 >> bitcast<u32>(8i))) * 0.000000059604645f);
}

fn mxc_light_kinds_u0028_() -> i32 {
    return 7i;
}

fn mxc_light_count_u0028_() -> i32 {
    var local_19: i32;

    if false {
        local_19 = MXC_LIGHT_COUNT;
    } else {
        let _e116 = mxc_view.counts[0u];
        local_19 = _e116;
    }
    let _e117 = local_19;
    return min(_e117, 8i);
}

fn mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b(mu_2: ptr<function, f32>, x_3: ptr<function, f32>, firstRow: ptr<function, f32>) -> vec4<f32> {
    var t_3: vec2<f32>;

    let _e117 = (*mu_2);
    let _e120 = (*x_3);
    t_3 = ((vec2<f32>(sqrt(clamp(_e117, 0f, 1f)), clamp(_e120, 0f, 1f)) * 31f) + vec2(0.5f));
    let _e127 = t_3[0u];
    let _e129 = (*firstRow);
    let _e131 = t_3[1u];
    let _e135 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, vec2<f32>((_e127 / 32f), ((_e129 + _e131) / 1654f)), 0f);
    return _e135;
}

fn mxc_table_u0028_f1_u003b_f1_u003b(mu_3: ptr<function, f32>, x_4: ptr<function, f32>) -> vec4<f32> {
    var param_117: f32;
    var param_118: f32;
    var param_119: f32;

    let _e118 = (*mu_3);
    param_117 = _e118;
    let _e119 = (*x_4);
    param_118 = _e119;
    param_119 = 0f;
    let _e120 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_117), (&param_118), (&param_119));
    return _e120;
}

fn mxc_split_sum_u0028_f1_u003b_f1_u003b(mu_4: ptr<function, f32>, alpha_8: ptr<function, f32>) -> vec2<f32> {
    var param_120: f32;
    var param_121: f32;

    let _e117 = (*alpha_8);
    let _e120 = (*mu_4);
    param_120 = _e120;
    param_121 = sqrt(max(_e117, 0f));
    let _e121 = mxc_table_u0028_f1_u003b_f1_u003b((&param_120), (&param_121));
    return _e121.xy;
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

    let _e127 = (*e);
    s_10 = (sqrt(clamp((0.5f * (_e127 - 1f)), 0f, 1f)) * 31f);
    let _e133 = s_10;
    s0_ = min(floor(_e133), 30f);
    let _e136 = (*alpha_9);
    x_5 = sqrt(max(_e136, 0f));
    let _e139 = s0_;
    let _e142 = (*mu_5);
    param_122 = _e142;
    let _e143 = x_5;
    param_123 = _e143;
    param_124 = (32f * (1f + _e139));
    let _e144 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_122), (&param_123), (&param_124));
    a_5 = _e144;
    let _e145 = s0_;
    let _e148 = (*mu_5);
    param_125 = _e148;
    let _e149 = x_5;
    param_126 = _e149;
    param_127 = (32f * (2f + _e145));
    let _e150 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_125), (&param_126), (&param_127));
    b_2 = _e150;
    let _e151 = a_5;
    let _e152 = b_2;
    let _e153 = s_10;
    let _e154 = s0_;
    return mix(_e151, _e152, vec4((_e153 - _e154)));
}

fn mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b(mu_6: ptr<function, f32>, alpha_10: ptr<function, f32>, eta_1: ptr<function, f32>) -> f32 {
    var e_1: f32;
    var local_20: f32;
    var param_128: f32;
    var param_129: f32;
    var param_130: f32;

    let _e121 = (*eta_1);
    if (_e121 >= 1f) {
        let _e123 = (*eta_1);
        local_20 = _e123;
    } else {
        let _e124 = (*eta_1);
        local_20 = (1f / max(_e124, 0.001f));
    }
    let _e127 = local_20;
    e_1 = _e127;
    let _e128 = (*mu_6);
    param_128 = _e128;
    let _e129 = (*alpha_10);
    param_129 = _e129;
    let _e130 = e_1;
    param_130 = _e130;
    let _e131 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_128), (&param_129), (&param_130));
    return _e131.x;
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
    var phi_2075_: bool;
    var phi_2082_: bool;
    var phi_2100_: bool;

    let _e141 = (*wo_11)[2u];
    mu_7 = clamp(_e141, 0f, 1f);
    let _e144 = (*l_10).kind;
    let _e145 = (_e144 == 1i);
    phi_2075_ = _e145;
    if !(_e145) {
        let _e148 = (*l_10).kind;
        phi_2075_ = (_e148 == 2i);
    }
    let _e151 = phi_2075_;
    phi_2082_ = _e151;
    if !(_e151) {
        let _e154 = (*l_10).kind;
        phi_2082_ = (_e154 == 3i);
    }
    let _e157 = phi_2082_;
    if _e157 {
        let _e160 = (*l_10).alpha[0u];
        let _e163 = (*l_10).alpha[1u];
        alpha_11 = sqrt((_e160 * _e163));
        let _e167 = (*l_10).kind;
        let _e168 = (_e167 == 1i);
        phi_2100_ = _e168;
        if _e168 {
            let _e170 = (*l_10).alpha;
            param_131 = _e170;
            let _e171 = mxc_is_delta_u0028_vf2_u003b((&param_131));
            phi_2100_ = !(_e171);
        }
        let _e174 = phi_2100_;
        if _e174 {
            let _e175 = mu_7;
            param_132 = _e175;
            let _e176 = alpha_11;
            param_133 = _e176;
            let _e178 = (*l_10).eta;
            param_134 = _e178;
            let _e179 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_132), (&param_133), (&param_134));
            e_2 = vec3(_e179);
            let _e181 = e_2;
            let _e183 = (*l_10).c0_;
            let _e185 = (*ms);
            return clamp(((_e181 * _e183) * _e185), vec3(0f), vec3(1f));
        }
        let _e190 = mu_7;
        param_135 = _e190;
        let _e191 = alpha_11;
        param_136 = _e191;
        let _e192 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_135), (&param_136));
        ab = _e192;
        let _e193 = (*l_10);
        param_137 = _e193;
        param_138 = 1f;
        param_139 = true;
        let _e194 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_137), (&param_138), (&param_139));
        f0_ = _e194;
        let _e195 = (*l_10);
        param_140 = _e195;
        param_141 = 0f;
        param_142 = true;
        let _e196 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_140), (&param_141), (&param_142));
        f90_ = _e196;
        let _e198 = (*l_10).kind;
        if (_e198 == 1i) {
            let _e201 = (*l_10).c0_;
            local_21 = _e201;
        } else {
            local_21 = vec3<f32>(1f, 1f, 1f);
        }
        let _e202 = local_21;
        tint_1 = _e202;
        let _e204 = (*l_10).alpha;
        param_143 = _e204;
        let _e205 = mxc_is_delta_u0028_vf2_u003b((&param_143));
        if _e205 {
            let _e206 = (*l_10);
            param_144 = _e206;
            let _e207 = mu_7;
            param_145 = _e207;
            param_146 = true;
            let _e208 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_144), (&param_145), (&param_146));
            let _e209 = tint_1;
            return (_e208 * _e209);
        }
        let _e211 = f0_;
        let _e213 = ab[0u];
        let _e215 = f90_;
        let _e217 = ab[1u];
        let _e220 = tint_1;
        let _e222 = (*ms);
        return clamp(((((_e211 * _e213) + (_e215 * _e217)) * _e220) * _e222), vec3(0f), vec3(1f));
    }
    let _e228 = (*l_10).kind;
    if (_e228 == 8i) {
        let _e231 = (*l_10).c0_;
        return _e231;
    }
    let _e233 = (*l_10).c0_;
    return _e233;
}

fn mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_11: ptr<function, MxcLobe>, woLocal: ptr<function, vec3<f32>>, ms_1: ptr<function, vec3<f32>>) -> f32 {
    var param_147: MxcLobe;
    var param_148: vec3<f32>;
    var param_149: vec3<f32>;
    var param_150: vec3<f32>;

    let _e121 = (*l_11).weight;
    if all((_e121 == vec3<f32>(0f, 0f, 0f))) {
        return 0f;
    }
    let _e125 = (*l_11).weight;
    let _e126 = (*l_11);
    param_147 = _e126;
    let _e127 = (*woLocal);
    param_148 = _e127;
    let _e128 = (*ms_1);
    param_149 = _e128;
    let _e129 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_147), (&param_148), (&param_149));
    param_150 = (_e125 * _e129);
    let _e131 = mxc_luminance_u0028_vf3_u003b((&param_150));
    return (max(_e131, 0f) + 0.0001f);
}

fn mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b(mu_8: ptr<function, f32>, alpha_12: ptr<function, f32>, eta_2: ptr<function, f32>) -> f32 {
    var param_151: f32;
    var param_152: f32;
    var param_153: f32;
    var param_154: f32;
    var param_155: f32;
    var param_156: f32;

    let _e122 = (*eta_2);
    if (_e122 >= 1f) {
        let _e124 = (*mu_8);
        param_151 = _e124;
        let _e125 = (*alpha_12);
        param_152 = _e125;
        let _e126 = (*eta_2);
        param_153 = _e126;
        let _e127 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_151), (&param_152), (&param_153));
        return _e127.y;
    }
    let _e129 = (*eta_2);
    let _e132 = (*mu_8);
    param_154 = _e132;
    let _e133 = (*alpha_12);
    param_155 = _e133;
    param_156 = (1f / max(_e129, 0.001f));
    let _e134 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_154), (&param_155), (&param_156));
    return _e134.z;
}

fn mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_12: ptr<function, MxcLobe>) -> bool {
    let _e115 = (*l_12).eta;
    return (abs((_e115 - 1f)) < 0.0001f);
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
    var phi_1951_: bool;
    var phi_1958_: bool;
    var phi_1967_: bool;
    var phi_1983_: bool;
    var phi_1995_: bool;

    let _e134 = (*l_13).kind;
    let _e135 = (_e134 == 1i);
    phi_1951_ = _e135;
    if !(_e135) {
        let _e138 = (*l_13).kind;
        phi_1951_ = (_e138 == 2i);
    }
    let _e141 = phi_1951_;
    phi_1958_ = _e141;
    if !(_e141) {
        let _e144 = (*l_13).kind;
        phi_1958_ = (_e144 == 3i);
    }
    let _e147 = phi_1958_;
    microfacet = _e147;
    let _e148 = microfacet;
    let _e149 = !(_e148);
    phi_1967_ = _e149;
    if !(_e149) {
        let _e152 = (*l_13).alpha;
        param_157 = _e152;
        let _e153 = mxc_is_delta_u0028_vf2_u003b((&param_157));
        phi_1967_ = _e153;
    }
    let _e155 = phi_1967_;
    if _e155 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e158 = (*l_13).alpha[0u];
    let _e161 = (*l_13).alpha[1u];
    alpha_13 = sqrt((_e158 * _e161));
    let _e165 = (*l_13).kind;
    let _e166 = (_e165 == 1i);
    phi_1983_ = _e166;
    if _e166 {
        let _e167 = (*l_13);
        param_158 = _e167;
        let _e168 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_158));
        phi_1983_ = _e168;
    }
    let _e170 = phi_1983_;
    if _e170 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e172 = (*l_13).kind;
    let _e173 = (_e172 == 1i);
    phi_1995_ = _e173;
    if _e173 {
        let _e175 = (*l_13).mode;
        phi_1995_ = ((_e175 & 4i) == 0i);
    }
    let _e179 = phi_1995_;
    if _e179 {
        let _e181 = (*wo_12)[2u];
        let _e184 = (*wo_12)[2u];
        let _e186 = (*l_13);
        param_159 = _e186;
        param_160 = (_e184 >= 0f);
        let _e187 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_159), (&param_160));
        param_161 = abs(_e181);
        let _e188 = alpha_13;
        param_162 = _e188;
        param_163 = _e187;
        let _e189 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_161), (&param_162), (&param_163));
        e_3 = _e189;
        let _e190 = e_3;
        k_3 = vec3((1f / max(_e190, 0.05f)));
        let _e194 = k_3;
        return _e194;
    }
    let _e196 = (*wo_12)[2u];
    param_164 = max(_e196, 0f);
    let _e198 = alpha_13;
    param_165 = _e198;
    let _e199 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_164), (&param_165));
    ab_1 = _e199;
    let _e201 = ab_1[0u];
    let _e203 = ab_1[1u];
    e_4 = (_e201 + _e203);
    let _e205 = (*l_13);
    param_166 = _e205;
    param_167 = 1f;
    param_168 = true;
    let _e206 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_166), (&param_167), (&param_168));
    let _e207 = e_4;
    let _e210 = e_4;
    return (vec3(1f) + ((_e206 * (1f - _e207)) / vec3(max(_e210, 0.05f))));
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
        let _e128 = k_4;
        let _e130 = (*c_8).count;
        if (_e128 < _e130) {
            let _e132 = k_4;
            let _e135 = (*c_8).lobes[_e132];
            l_14 = _e135;
            let _e136 = k_4;
            (*c_8).ms[_e136] = vec3<f32>(1f, 1f, 1f);
            let _e139 = k_4;
            (*c_8).choice[_e139] = 0f;
            let _e143 = l_14.weight;
            if all((_e143 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e147 = l_14.N;
            param_169 = _e147;
            let _e149 = l_14.T;
            param_170 = _e149;
            let _e150 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_169), (&param_170));
            param_171 = _e150;
            let _e151 = (*wo_13);
            param_172 = _e151;
            let _e152 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_171), (&param_172));
            o_4 = _e152;
            let _e153 = k_4;
            let _e154 = l_14;
            param_173 = _e154;
            let _e155 = o_4;
            param_174 = _e155;
            let _e156 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_173), (&param_174));
            (*c_8).ms[_e153] = _e156;
            let _e159 = k_4;
            let _e160 = k_4;
            let _e161 = l_14;
            param_175 = _e161;
            let _e162 = o_4;
            param_176 = _e162;
            let _e165 = (*c_8).ms[_e160];
            param_177 = _e165;
            let _e166 = mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_175), (&param_176), (&param_177));
            (*c_8).choice[_e159] = _e166;
            let _e169 = k_4;
            let _e172 = (*c_8).choice[_e169];
            let _e174 = (*c_8).choiceTotal;
            (*c_8).choiceTotal = (_e174 + _e172);
            continue;
        } else {
            break;
        }
        continuing {
            let _e177 = k_4;
            k_4 = (_e177 + 1i);
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

    let _e120 = (*l_15);
    param_178 = _e120;
    let _e121 = (*wo_14);
    param_179 = _e121;
    let _e122 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_178), (&param_179));
    let _e123 = (*l_15);
    param_180 = _e123;
    let _e124 = (*wo_14);
    param_181 = _e124;
    param_182 = _e122;
    let _e125 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_180), (&param_181), (&param_182));
    return _e125;
}

fn mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_16: ptr<function, MxcLobe>, wo_15: ptr<function, vec3<f32>>) -> vec3<f32> {
    var white: MxcLobe;
    var param_183: MxcLobe;
    var param_184: vec3<f32>;
    var param_185: MxcLobe;
    var param_186: vec3<f32>;
    var phi_2202_: bool;

    let _e121 = (*l_16).kind;
    let _e122 = (_e121 == 9i);
    phi_2202_ = _e122;
    if !(_e122) {
        let _e125 = (*l_16).kind;
        phi_2202_ = (_e125 == 10i);
    }
    let _e128 = phi_2202_;
    if _e128 {
        let _e129 = (*l_16);
        white = _e129;
        white.c0_ = vec3<f32>(1f, 1f, 1f);
        let _e131 = white;
        param_183 = _e131;
        let _e132 = (*wo_15);
        param_184 = _e132;
        let _e133 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_183), (&param_184));
        return _e133;
    }
    let _e134 = (*l_16);
    param_185 = _e134;
    let _e135 = (*wo_15);
    param_186 = _e135;
    let _e136 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_185), (&param_186));
    return _e136;
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

    let _e131 = (*g_1).N;
    v5_ = _e131;
    let _e133 = (*g_1).T;
    v6_ = _e133;
    (*c_9).emission = vec3<f32>(0f, 0f, 0f);
    (*c_9).transparency = vec3<f32>(0f, 0f, 0f);
    lobe0_.kind = 1i;
    lobe0_.mode = 1i;
    let _e138 = v5_;
    lobe0_.N = _e138;
    let _e140 = v6_;
    lobe0_.T = _e140;
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
    let _e153 = lobe0_.N;
    param_187 = _e153;
    let _e155 = lobe0_.T;
    param_188 = _e155;
    let _e156 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_187), (&param_188));
    param_189 = _e156;
    let _e157 = (*wo_16);
    param_190 = _e157;
    let _e158 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_189), (&param_190));
    let _e159 = lobe0_;
    param_191 = _e159;
    param_192 = _e158;
    let _e160 = mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_191), (&param_192));
    e1_ = _e160;
    let _e161 = e1_;
    w2_ = (vec3<f32>(1f, 1f, 1f) - _e161);
    lobe3_.kind = 5i;
    lobe3_.mode = 1i;
    let _e165 = v5_;
    lobe3_.N = _e165;
    let _e168 = (*g_1).T;
    lobe3_.T = _e168;
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
    let _e181 = lobe0_;
    (*c_9).lobes[0i] = _e181;
    let _e184 = w2_;
    lobe3_.weight = _e184;
    let _e186 = lobe3_;
    (*c_9).lobes[1i] = _e186;
    (*c_9).count = 2i;
    let _e190 = (*c_9);
    param_193 = _e190;
    let _e191 = (*wo_16);
    param_194 = _e191;
    mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b((&param_193), (&param_194));
    let _e192 = param_193;
    (*c_9) = _e192;
    return;
}

fn mxc_closure_seed_u0028_u1_u003b(seed_1: ptr<function, u32>) {
    return;
}

fn mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b(v_6: ptr<function, vec3<f32>>, fallback: ptr<function, vec3<f32>>) -> vec3<f32> {
    var l2_1: f32;
    var local_22: vec3<f32>;

    let _e117 = (*v_6);
    let _e118 = (*v_6);
    l2_1 = dot(_e117, _e118);
    let _e120 = l2_1;
    if (_e120 > 0.00000000000000000001f) {
        let _e122 = (*v_6);
        let _e123 = l2_1;
        local_22 = (_e122 * inverseSqrt(_e123));
    } else {
        let _e126 = (*fallback);
        local_22 = _e126;
    }
    let _e127 = local_22;
    return _e127;
}

fn main_1() {
    var g_2: MxcGeometry;
    var N_1: vec3<f32>;
    var param_195: vec3<f32>;
    var param_196: vec3<f32>;
    var wo_17: vec3<f32>;
    var param_197: vec3<f32>;
    var param_198: vec3<f32>;
    var facing: f32;
    var handedness: f32;
    var frame_4: mat3x3<f32>;
    var param_199: vec3<f32>;
    var param_200: vec3<f32>;
    var param_201: vec3<f32>;
    var param_202: vec3<f32>;
    var objectFrame: mat3x3<f32>;
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
    var phi_615_: bool;
    var phi_626_: bool;
    var phi_688_: bool;
    var phi_745_: bool;
    var phi_746_: bool;
    var phi_779_: bool;
    var phi_821_: bool;

    let _e235 = vPosition_1;
    g_2.P = _e235;
    let _e237 = vObjectPosition_1;
    g_2.Pobj = _e237;
    let _e239 = vNormal_1;
    param_195 = _e239;
    param_196 = vec3<f32>(0f, 0f, 1f);
    let _e240 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_195), (&param_196));
    N_1 = _e240;
    let _e241 = gl_FrontFacing_1;
    if !(_e241) {
        let _e243 = N_1;
        N_1 = -(_e243);
    }
    let _e246 = mxc_view.eye;
    let _e248 = vPosition_1;
    param_197 = (_e246.xyz - _e248);
    let _e250 = N_1;
    param_198 = _e250;
    let _e251 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_197), (&param_198));
    wo_17 = _e251;
    let _e252 = wo_17;
    let _e253 = N_1;
    facing = dot(_e252, _e253);
    let _e255 = facing;
    if (_e255 < 0.01f) {
        let _e257 = N_1;
        let _e258 = facing;
        let _e260 = wo_17;
        N_1 = normalize((_e257 + (_e260 * (0.01f - _e258))));
    }
    let _e265 = vTangent_1[3u];
    handedness = select(1f, -1f, (_e265 < 0f));
    let _e268 = N_1;
    param_199 = _e268;
    let _e269 = vTangent_1;
    param_200 = _e269.xyz;
    let _e271 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_199), (&param_200));
    frame_4 = _e271;
    let _e272 = N_1;
    g_2.N = _e272;
    let _e275 = frame_4[0];
    g_2.T = _e275;
    let _e278 = frame_4[1];
    let _e279 = handedness;
    g_2.B = (_e278 * _e279);
    let _e282 = vObjectNormal_1;
    param_201 = _e282;
    param_202 = vec3<f32>(0f, 0f, 1f);
    let _e283 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_201), (&param_202));
    g_2.Nobj = _e283;
    let _e286 = g_2.Nobj;
    param_203 = _e286;
    let _e287 = vObjectTangent_1;
    param_204 = _e287;
    let _e288 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_203), (&param_204));
    objectFrame = _e288;
    let _e290 = objectFrame[0];
    g_2.Tobj = _e290;
    let _e293 = objectFrame[1];
    let _e294 = handedness;
    g_2.Bobj = (_e293 * _e294);
    let _e297 = vUv_1;
    g_2.uv = _e297;
    g_2.color = vec4<f32>(1f, 1f, 1f, 1f);
    let _e301 = mxc_view.objectToWorld;
    g_2.objectToWorld = _e301;
    let _e304 = mxc_params.frame;
    g_2.frame = _e304;
    let _e307 = mxc_params.time;
    g_2.time = _e307;
    let _e310 = gl_FragCoord_1[0u];
    let _e313 = gl_FragCoord_1[1u];
    let _e317 = mxc_view.counts[2u];
    param_205 = (bitcast<u32>(_e317) + 7u);
    let _e320 = mxc_pcg_u0028_u1_u003b((&param_205));
    param_206 = (u32(_e313) + _e320);
    let _e322 = mxc_pcg_u0028_u1_u003b((&param_206));
    param_207 = (u32(_e310) ^ _e322);
    let _e324 = mxc_pcg_u0028_u1_u003b((&param_207));
    param_208 = _e324;
    mxc_closure_seed_u0028_u1_u003b((&param_208));
    let _e325 = g_2;
    param_209 = _e325;
    let _e326 = wo_17;
    param_210 = _e326;
    mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b((&param_209), (&param_210), (&param_211));
    let _e327 = param_211;
    c_10 = _e327;
    let _e329 = c_10.emission;
    let _e332 = mxc_view.environment[1u];
    radiance = (_e329 * _e332);
    let _e334 = mxc_light_count_u0028_();
    lights = _e334;
    let _e335 = mxc_light_kinds_u0028_();
    kinds = _e335;
    let _e336 = mxc_environment_code_u0028_();
    image = (_e336 == 3i);
    let _e338 = mxc_environment_code_u0028_();
    if (_e338 != 0i) {
        let _e342 = mxc_view.counts[3u];
        local_23 = max(_e342, 1i);
    } else {
        local_23 = 0i;
    }
    let _e344 = local_23;
    n_1 = _e344;
    let _e346 = gl_FragCoord_1[0u];
    let _e349 = gl_FragCoord_1[1u];
    let _e353 = mxc_view.counts[2u];
    param_212 = bitcast<u32>(_e353);
    let _e355 = mxc_pcg_u0028_u1_u003b((&param_212));
    param_213 = (u32(_e349) + _e355);
    let _e357 = mxc_pcg_u0028_u1_u003b((&param_213));
    param_214 = (u32(_e346) + _e357);
    let _e359 = mxc_pcg_u0028_u1_u003b((&param_214));
    seed_2 = _e359;
    let _e361 = gl_FragCoord_1[0u];
    let _e364 = gl_FragCoord_1[1u];
    param_215 = (u32(_e364) + 2654435769u);
    let _e367 = mxc_pcg_u0028_u1_u003b((&param_215));
    param_216 = (u32(_e361) ^ _e367);
    let _e369 = mxc_pcg_u0028_u1_u003b((&param_216));
    pixel = _e369;
    let _e370 = pixel;
    param_217 = _e370;
    let _e371 = mxc_uniform_u0028_u1_u003b((&param_217));
    let _e372 = param_217;
    pixel = _e372;
    let _e373 = pixel;
    param_218 = _e373;
    let _e374 = mxc_uniform_u0028_u1_u003b((&param_218));
    let _e375 = param_218;
    pixel = _e375;
    let _e376 = pixel;
    param_219 = _e376;
    let _e377 = mxc_uniform_u0028_u1_u003b((&param_219));
    let _e378 = param_219;
    pixel = _e378;
    let _e379 = pixel;
    param_220 = _e379;
    let _e380 = mxc_uniform_u0028_u1_u003b((&param_220));
    let _e381 = param_220;
    pixel = _e381;
    shift = vec4<f32>(_e371, _e374, _e377, _e380);
    sum = vec3<f32>(0f, 0f, 0f);
    b_3 = 0i;
    loop {
        let _e383 = b_3;
        let _e384 = n_1;
        let _e385 = lights;
        if (_e383 < max(_e384, select(0i, 1i, (_e385 > 0i)))) {
            let _e390 = b_3;
            let _e392 = lights;
            batchLights = select(0i, _e392, (_e390 == 0i));
            let _e394 = b_3;
            let _e395 = n_1;
            if (_e394 < _e395) {
                let _e397 = image;
                local_24 = (1i + select(0i, 1i, _e397));
            } else {
                local_24 = 0i;
            }
            let _e400 = local_24;
            batchSamples = _e400;
            let _e403 = mxc_view.counts[2u];
            let _e405 = n_1;
            let _e409 = b_3;
            index = ((bitcast<u32>(_e403) * bitcast<u32>(max(_e405, 1i))) + bitcast<u32>(_e409));
            let _e412 = index;
            param_221 = _e412;
            param_222 = 2u;
            let _e413 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_221), (&param_222));
            let _e414 = index;
            param_223 = _e414;
            param_224 = 3u;
            let _e415 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_223), (&param_224));
            let _e416 = index;
            param_225 = _e416;
            param_226 = 5u;
            let _e417 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_225), (&param_226));
            let _e418 = index;
            param_227 = _e418;
            param_228 = 7u;
            let _e419 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_227), (&param_228));
            let _e421 = shift;
            choice = fract((vec4<f32>(_e413, _e415, _e417, _e419) + _e421));
            smp.valid = false;
            smp.evaluate = false;
            smp.delta = false;
            smp.pdf = 0f;
            smp.weight = vec3<f32>(0f, 0f, 0f);
            let _e429 = N_1;
            smp.wi = _e429;
            let _e431 = n_1;
            if (_e431 > 0i) {
                let _e434 = choice[2u];
                let _e436 = choice[3u];
                let _e438 = choice[0u];
                let _e440 = c_10;
                param_229 = _e440;
                let _e441 = wo_17;
                param_230 = _e441;
                param_231 = vec3<f32>(_e434, _e436, _e438);
                let _e442 = mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b((&param_229), (&param_230), (&param_231));
                smp = _e442;
            }
            let _e444 = smp.wi;
            let _e445 = N_1;
            above_4 = (dot(_e444, _e445) > 0f);
            let _e449 = smp.valid;
            if _e449 {
                let _e450 = above_4;
                if _e450 {
                    let _e452 = smp.wi;
                    local_26 = _e452;
                } else {
                    let _e453 = wo_17;
                    param_232 = -(_e453);
                    let _e456 = smp.wi;
                    param_233 = _e456;
                    let _e457 = mxc_exit_direction_u0028_vf3_u003b_vf3_u003b((&param_232), (&param_233));
                    local_26 = _e457;
                }
                let _e458 = local_26;
                param_234 = _e458;
                let _e459 = mxc_environment_u0028_vf3_u003b((&param_234));
                local_25 = _e459;
            } else {
                local_25 = vec3<f32>(0f, 0f, 0f);
            }
            let _e460 = local_25;
            seen = _e460;
            let _e461 = b_3;
            let _e462 = n_1;
            let _e465 = smp.valid;
            let _e466 = ((_e461 < _e462) && _e465);
            phi_615_ = _e466;
            if _e466 {
                let _e468 = smp.evaluate;
                phi_615_ = !(_e468);
            }
            let _e471 = phi_615_;
            if _e471 {
                let _e472 = image;
                let _e473 = above_4;
                let _e474 = (_e472 && _e473);
                phi_626_ = _e474;
                if _e474 {
                    let _e476 = smp.delta;
                    phi_626_ = !(_e476);
                }
                let _e479 = phi_626_;
                if _e479 {
                    let _e481 = smp.wi;
                    param_235 = _e481;
                    let _e484 = mxc_view.environment[2u];
                    param_236 = _e484;
                    let _e485 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_235), (&param_236));
                    param_237 = _e485;
                    let _e486 = mxc_env_pdf_u0028_vf3_u003b((&param_237));
                    let _e488 = smp.pdf;
                    param_238 = _e488;
                    param_239 = _e486;
                    let _e489 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_238), (&param_239));
                    local_27 = _e489;
                } else {
                    local_27 = 1f;
                }
                let _e490 = local_27;
                w_1 = _e490;
                let _e491 = w_1;
                let _e493 = smp.weight;
                let _e495 = seen;
                let _e497 = sum;
                sum = (_e497 + ((_e493 * _e491) * _e495));
            }
            m_5 = vec3<f32>(0f, 0f, 0f);
            lightPdf = 0f;
            let _e499 = N_1;
            imageWi = _e499;
            imageSeen = vec3<f32>(0f, 0f, 0f);
            let _e500 = image;
            let _e501 = b_3;
            let _e502 = n_1;
            if (_e500 && (_e501 < _e502)) {
                let _e506 = choice[1u];
                let _e507 = seed_2;
                param_240 = _e507;
                let _e508 = mxc_uniform_u0028_u1_u003b((&param_240));
                let _e509 = param_240;
                seed_2 = _e509;
                let _e510 = seed_2;
                param_241 = _e510;
                let _e511 = mxc_uniform_u0028_u1_u003b((&param_241));
                let _e512 = param_241;
                seed_2 = _e512;
                let _e513 = seed_2;
                param_242 = _e513;
                let _e514 = mxc_uniform_u0028_u1_u003b((&param_242));
                let _e515 = param_242;
                seed_2 = _e515;
                v_7 = vec4<f32>(_e506, _e508, _e511, _e514);
                let _e517 = v_7;
                param_243 = _e517;
                let _e518 = mxc_env_sample_u0028_vf4_u003b_f1_u003b((&param_243), (&param_244));
                let _e519 = param_244;
                lightPdf = _e519;
                m_5 = _e518;
                let _e520 = m_5;
                param_245 = _e520;
                let _e523 = mxc_view.environment[2u];
                param_246 = _e523;
                let _e524 = mxc_env_to_world_u0028_vf3_u003b_f1_u003b((&param_245), (&param_246));
                imageWi = _e524;
                let _e525 = lightPdf;
                let _e526 = (_e525 > 0f);
                phi_688_ = _e526;
                if _e526 {
                    let _e527 = imageWi;
                    let _e528 = N_1;
                    phi_688_ = (dot(_e527, _e528) > 0f);
                }
                let _e532 = phi_688_;
                if _e532 {
                    let _e533 = imageWi;
                    param_247 = _e533;
                    let _e534 = mxc_environment_u0028_vf3_u003b((&param_247));
                    imageSeen = _e534;
                }
            }
            j_2 = 0i;
            loop {
                let _e535 = j_2;
                let _e536 = batchLights;
                let _e537 = batchSamples;
                if (_e535 < (_e536 + _e537)) {
                    let _e540 = N_1;
                    wi_7 = _e540;
                    incoming = vec3<f32>(0f, 0f, 0f);
                    use_ = true;
                    let _e541 = n_1;
                    let _e543 = j_2;
                    let _e544 = batchLights;
                    if ((_e541 == 0i) || (_e543 < _e544)) {
                        local_28 = 0i;
                    } else {
                        let _e547 = j_2;
                        let _e548 = batchLights;
                        local_28 = select(2i, 1i, (_e547 == ((_e548 + 1i) - 1i)));
                    }
                    let _e553 = local_28;
                    strategy = _e553;
                    let _e554 = strategy;
                    if (_e554 == 0i) {
                        let _e556 = j_2;
                        let _e559 = mxc_view.lightVector[_e556];
                        light = _e559;
                        let _e560 = j_2;
                        let _e563 = mxc_view.lightRadiance[_e560];
                        incoming = _e563.xyz;
                        let _e565 = kinds;
                        let _e566 = (_e565 == 1i);
                        phi_746_ = _e566;
                        if !(_e566) {
                            let _e568 = kinds;
                            let _e570 = ((_e568 & 1i) != 0i);
                            phi_745_ = _e570;
                            if _e570 {
                                let _e572 = light[3u];
                                phi_745_ = (_e572 == 0f);
                            }
                            let _e575 = phi_745_;
                            phi_746_ = _e575;
                        }
                        let _e577 = phi_746_;
                        directional = _e577;
                        let _e578 = directional;
                        if _e578 {
                            let _e579 = light;
                            param_248 = _e579.xyz;
                            let _e581 = N_1;
                            param_249 = _e581;
                            let _e582 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_248), (&param_249));
                            wi_7 = _e582;
                        } else {
                            let _e583 = light;
                            let _e585 = vPosition_1;
                            d_8 = (_e583.xyz - _e585);
                            let _e587 = d_8;
                            let _e588 = d_8;
                            d2_ = max(dot(_e587, _e588), 0.00000001f);
                            let _e591 = d_8;
                            let _e592 = d2_;
                            wi_7 = (_e591 * inverseSqrt(_e592));
                            let _e595 = d2_;
                            let _e596 = incoming;
                            incoming = (_e596 / vec3(_e595));
                            let _e599 = kinds;
                            let _e601 = ((_e599 & 4i) != 0i);
                            phi_779_ = _e601;
                            if _e601 {
                                let _e603 = light[3u];
                                phi_779_ = (_e603 == 2f);
                            }
                            let _e606 = phi_779_;
                            if _e606 {
                                let _e607 = j_2;
                                let _e610 = mxc_view.lightSpot[_e607];
                                spot = _e610;
                                let _e612 = spot[3u];
                                let _e613 = j_2;
                                let _e617 = mxc_view.lightRadiance[_e613][3u];
                                let _e618 = wi_7;
                                let _e620 = spot;
                                let _e624 = incoming;
                                incoming = (_e624 * smoothstep(_e612, _e617, dot(-(_e618), _e620.xyz)));
                            }
                        }
                    } else {
                        let _e626 = strategy;
                        if (_e626 == 1i) {
                            let _e629 = smp.wi;
                            wi_7 = _e629;
                            let _e630 = seen;
                            incoming = _e630;
                            let _e632 = smp.valid;
                            let _e634 = smp.evaluate;
                            use_ = (_e632 && _e634);
                        } else {
                            let _e636 = imageWi;
                            wi_7 = _e636;
                            let _e637 = imageSeen;
                            incoming = _e637;
                            let _e638 = lightPdf;
                            let _e639 = (_e638 > 0f);
                            phi_821_ = _e639;
                            if _e639 {
                                let _e640 = imageWi;
                                let _e641 = N_1;
                                phi_821_ = (dot(_e640, _e641) > 0f);
                            }
                            let _e645 = phi_821_;
                            use_ = _e645;
                        }
                    }
                    let _e646 = strategy;
                    let _e648 = c_10;
                    param_250 = _e648;
                    let _e649 = wo_17;
                    param_251 = _e649;
                    let _e650 = wi_7;
                    param_252 = _e650;
                    param_253 = (_e646 != 0i);
                    let _e651 = mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b((&param_250), (&param_251), (&param_252), (&param_253), (&param_254));
                    let _e652 = param_254;
                    pdf_2 = _e652;
                    f_6 = _e651;
                    let _e653 = strategy;
                    if (_e653 == 0i) {
                        let _e655 = f_6;
                        let _e656 = incoming;
                        let _e658 = radiance;
                        radiance = (_e658 + (_e655 * _e656));
                    } else {
                        let _e660 = strategy;
                        if (_e660 == 1i) {
                            let _e662 = use_;
                            let _e663 = pdf_2;
                            if (_e662 && (_e663 > 0f)) {
                                let _e666 = image;
                                let _e667 = above_4;
                                if (_e666 && _e667) {
                                    let _e669 = wi_7;
                                    param_255 = _e669;
                                    let _e672 = mxc_view.environment[2u];
                                    param_256 = _e672;
                                    let _e673 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_255), (&param_256));
                                    param_257 = _e673;
                                    let _e674 = mxc_env_pdf_u0028_vf3_u003b((&param_257));
                                    let _e675 = pdf_2;
                                    param_258 = _e675;
                                    param_259 = _e674;
                                    let _e676 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_258), (&param_259));
                                    local_29 = _e676;
                                } else {
                                    local_29 = 1f;
                                }
                                let _e677 = local_29;
                                w_2 = _e677;
                                let _e678 = w_2;
                                let _e679 = f_6;
                                let _e681 = pdf_2;
                                let _e684 = incoming;
                                let _e686 = sum;
                                sum = (_e686 + (((_e679 * _e678) / vec3(_e681)) * _e684));
                            }
                        } else {
                            let _e688 = use_;
                            if _e688 {
                                let _e689 = m_5;
                                param_260 = _e689;
                                let _e690 = mxc_env_pdf_u0028_vf3_u003b((&param_260));
                                param_261 = _e690;
                                let _e691 = pdf_2;
                                param_262 = _e691;
                                let _e692 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_261), (&param_262));
                                w_3 = _e692;
                                let _e693 = w_3;
                                let _e694 = f_6;
                                let _e696 = incoming;
                                let _e698 = lightPdf;
                                let _e701 = sum;
                                sum = (_e701 + (((_e694 * _e693) * _e696) / vec3(_e698)));
                            }
                        }
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e703 = j_2;
                    j_2 = (_e703 + 1i);
                }
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e705 = b_3;
            b_3 = (_e705 + 1i);
        }
    }
    let _e707 = sum;
    let _e708 = n_1;
    let _e713 = radiance;
    radiance = (_e713 + (_e707 / vec3(f32(max(_e708, 1i)))));
    let _e716 = c_10.transparency;
    param_263 = _e716;
    let _e717 = mxc_luminance_u0028_vf3_u003b((&param_263));
    coverage = (1f - clamp(_e717, 0f, 1f));
    let _e720 = radiance;
    let _e721 = coverage;
    outColor = vec4<f32>(_e720.x, _e720.y, _e720.z, _e721);
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
