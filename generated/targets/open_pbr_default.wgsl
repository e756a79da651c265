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
    etaAbove: f32,
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
    let _e126 = (*c);
    return dot(_e126, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b(l: ptr<function, MxcLobe>, mu: ptr<function, f32>) -> vec3<f32> {
    return vec3<f32>(1f, 1f, 1f);
}

fn mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_1: ptr<function, MxcLobe>) -> bool {
    return false;
}

fn mxc_mean_u0028_vf3_u003b(c_1: ptr<function, vec3<f32>>) -> f32 {
    let _e127 = (*c_1)[0u];
    let _e129 = (*c_1)[1u];
    let _e132 = (*c_1)[2u];
    return (((_e127 + _e129) + _e132) * 0.33333334f);
}

fn mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b(cosi: ptr<function, f32>, eta: ptr<function, f32>) -> f32 {
    var sin2t: f32;
    var cost: f32;
    var rs: f32;
    var rp: f32;

    let _e131 = (*eta);
    if (abs((_e131 - 1f)) < 0.000001f) {
        return 0f;
    }
    let _e135 = (*cosi);
    let _e136 = (*cosi);
    let _e139 = (*eta);
    let _e140 = (*eta);
    sin2t = ((1f - (_e135 * _e136)) / (_e139 * _e140));
    let _e143 = sin2t;
    if (_e143 >= 1f) {
        return 1f;
    }
    let _e145 = sin2t;
    cost = sqrt((1f - _e145));
    let _e148 = (*cosi);
    let _e149 = (*eta);
    let _e150 = cost;
    let _e153 = (*cosi);
    let _e154 = (*eta);
    let _e155 = cost;
    rs = ((_e148 - (_e149 * _e150)) / (_e153 + (_e154 * _e155)));
    let _e159 = (*eta);
    let _e160 = (*cosi);
    let _e162 = cost;
    let _e164 = (*eta);
    let _e165 = (*cosi);
    let _e167 = cost;
    rp = (((_e159 * _e160) - _e162) / ((_e164 * _e165) + _e167));
    let _e170 = rs;
    let _e171 = rs;
    let _e173 = rp;
    let _e174 = rp;
    return (0.5f * ((_e170 * _e171) + (_e173 * _e174)));
}

fn mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_2: ptr<function, MxcLobe>, above: ptr<function, bool>) -> f32 {
    var local: f32;

    let _e128 = (*above);
    if _e128 {
        let _e130 = (*l_2).eta;
        local = _e130;
    } else {
        let _e132 = (*l_2).eta;
        local = (1f / _e132);
    }
    let _e134 = local;
    return _e134;
}

fn mxc_lobe_cosine_below_coat_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b(l_3: ptr<function, MxcLobe>, mu_1: ptr<function, f32>) -> f32 {
    var phi_1757_: bool;

    let _e128 = (*l_3).kind;
    let _e129 = (_e128 == 1i);
    phi_1757_ = _e129;
    if _e129 {
        let _e131 = (*l_3).etaAbove;
        phi_1757_ = (_e131 > 1f);
    }
    let _e134 = phi_1757_;
    if _e134 {
        let _e135 = (*mu_1);
        let _e136 = (*mu_1);
        let _e140 = (*l_3).etaAbove;
        let _e142 = (*l_3).etaAbove;
        return sqrt((1f - ((1f - (_e135 * _e136)) / (_e140 * _e142))));
    }
    let _e147 = (*mu_1);
    return _e147;
}

fn mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b(l_4: ptr<function, MxcLobe>, cosh_: ptr<function, f32>, above_1: ptr<function, bool>) -> vec3<f32> {
    var f: vec3<f32>;
    var param: MxcLobe;
    var param_1: f32;
    var param_2: MxcLobe;
    var param_3: bool;
    var param_4: f32;
    var param_5: f32;

    f = vec3<f32>(1f, 1f, 1f);
    let _e135 = (*above_1);
    if _e135 {
        let _e136 = (*cosh_);
        let _e138 = (*l_4);
        param = _e138;
        param_1 = clamp(_e136, 0f, 1f);
        let _e139 = mxc_lobe_cosine_below_coat_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param), (&param_1));
        (*cosh_) = _e139;
    }
    let _e141 = (*l_4).kind;
    if (_e141 == 1i) {
        let _e143 = (*l_4);
        param_2 = _e143;
        let _e144 = (*above_1);
        param_3 = _e144;
        let _e145 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_2), (&param_3));
        let _e146 = (*cosh_);
        param_4 = _e146;
        param_5 = _e145;
        let _e147 = mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b((&param_4), (&param_5));
        f = vec3(_e147);
    }
    let _e149 = f;
    return _e149;
}

fn mxc_rough_alpha_u0028_vf2_u003b(alpha: ptr<function, vec2<f32>>) -> vec2<f32> {
    let _e126 = (*alpha);
    return max(_e126, vec2<f32>(0.0001f, 0.0001f));
}

fn mxc_ggx_d_u0028_vf3_u003b_vf2_u003b(m: ptr<function, vec3<f32>>, alpha_1: ptr<function, vec2<f32>>) -> f32 {
    var param_6: vec2<f32>;
    var s: vec3<f32>;
    var d: f32;

    let _e131 = (*m)[2u];
    if (_e131 <= 0f) {
        return 0f;
    }
    let _e133 = (*alpha_1);
    param_6 = _e133;
    let _e134 = mxc_rough_alpha_u0028_vf2_u003b((&param_6));
    (*alpha_1) = _e134;
    let _e136 = (*m)[0u];
    let _e138 = (*alpha_1)[0u];
    let _e141 = (*m)[1u];
    let _e143 = (*alpha_1)[1u];
    let _e146 = (*m)[2u];
    s = vec3<f32>((_e136 / _e138), (_e141 / _e143), _e146);
    let _e148 = s;
    let _e149 = s;
    d = dot(_e148, _e149);
    let _e152 = (*alpha_1)[0u];
    let _e155 = (*alpha_1)[1u];
    let _e157 = d;
    let _e159 = d;
    return (1f / ((((3.1415927f * _e152) * _e155) * _e157) * _e159));
}

fn mxc_sqr_u0028_f1_u003b(x: ptr<function, f32>) -> f32 {
    let _e126 = (*x);
    let _e127 = (*x);
    return (_e126 * _e127);
}

fn mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b(v: ptr<function, vec3<f32>>, alpha_2: ptr<function, vec2<f32>>) -> f32 {
    var param_7: vec2<f32>;
    var z2_: f32;
    var a2_: f32;
    var param_8: f32;
    var param_9: f32;

    let _e132 = (*alpha_2);
    param_7 = _e132;
    let _e133 = mxc_rough_alpha_u0028_vf2_u003b((&param_7));
    (*alpha_2) = _e133;
    let _e135 = (*v)[2u];
    let _e137 = (*v)[2u];
    z2_ = (_e135 * _e137);
    let _e139 = z2_;
    if (_e139 <= 0f) {
        return 10000000000f;
    }
    let _e142 = (*alpha_2)[0u];
    let _e144 = (*v)[0u];
    param_8 = (_e142 * _e144);
    let _e146 = mxc_sqr_u0028_f1_u003b((&param_8));
    let _e148 = (*alpha_2)[1u];
    let _e150 = (*v)[1u];
    param_9 = (_e148 * _e150);
    let _e152 = mxc_sqr_u0028_f1_u003b((&param_9));
    let _e154 = z2_;
    a2_ = ((_e146 + _e152) / _e154);
    let _e156 = a2_;
    return (0.5f * (-1f + sqrt((1f + _e156))));
}

fn mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b(v_1: ptr<function, vec3<f32>>, alpha_3: ptr<function, vec2<f32>>) -> f32 {
    var param_10: vec3<f32>;
    var param_11: vec2<f32>;

    let _e129 = (*v_1);
    param_10 = _e129;
    let _e130 = (*alpha_3);
    param_11 = _e130;
    let _e131 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_10), (&param_11));
    return (1f / (1f + _e131));
}

fn mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo: ptr<function, vec3<f32>>, m_1: ptr<function, vec3<f32>>, alpha_4: ptr<function, vec2<f32>>) -> f32 {
    var param_12: vec3<f32>;
    var param_13: vec2<f32>;
    var param_14: vec3<f32>;
    var param_15: vec2<f32>;

    let _e133 = (*wo)[2u];
    if (_e133 <= 0f) {
        return 0f;
    }
    let _e135 = (*wo);
    param_12 = _e135;
    let _e136 = (*alpha_4);
    param_13 = _e136;
    let _e137 = mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b((&param_12), (&param_13));
    let _e138 = (*wo);
    let _e139 = (*m_1);
    let _e143 = (*m_1);
    param_14 = _e143;
    let _e144 = (*alpha_4);
    param_15 = _e144;
    let _e145 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_14), (&param_15));
    let _e148 = (*wo)[2u];
    return (((_e137 * max(dot(_e138, _e139), 0f)) * _e145) / _e148);
}

fn mxc_is_delta_u0028_vf2_u003b(alpha_5: ptr<function, vec2<f32>>) -> bool {
    let _e127 = (*alpha_5)[0u];
    let _e129 = (*alpha_5)[1u];
    return (max(_e127, _e129) < 0.0001f);
}

fn mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_5: ptr<function, MxcLobe>, wo_1: ptr<function, vec3<f32>>, wi: ptr<function, vec3<f32>>) -> f32 {
    var param_16: vec2<f32>;
    var above_2: bool;
    var o: vec3<f32>;
    var local_1: vec3<f32>;
    var i: vec3<f32>;
    var local_2: vec3<f32>;
    var h: vec3<f32>;
    var p: f32;
    var param_17: vec3<f32>;
    var param_18: vec3<f32>;
    var param_19: vec2<f32>;
    var fr: f32;
    var param_20: MxcLobe;
    var param_21: f32;
    var param_22: bool;
    var param_23: vec3<f32>;
    var param_24: MxcLobe;
    var local_3: f32;
    var phi_2718_: bool;
    var phi_2799_: bool;

    let _e147 = (*l_5).kind;
    switch _e147 {
        case 2, 3, 1: {
            let _e161 = (*l_5).alpha;
            param_16 = _e161;
            let _e162 = mxc_is_delta_u0028_vf2_u003b((&param_16));
            if _e162 {
                return 0f;
            }
            let _e164 = (*wo_1)[2u];
            above_2 = (_e164 > 0f);
            let _e166 = above_2;
            if _e166 {
                let _e167 = (*wo_1);
                local_1 = _e167;
            } else {
                let _e168 = (*wo_1);
                local_1 = -(_e168);
            }
            let _e170 = local_1;
            o = _e170;
            let _e171 = above_2;
            if _e171 {
                let _e172 = (*wi);
                local_2 = _e172;
            } else {
                let _e173 = (*wi);
                local_2 = -(_e173);
            }
            let _e175 = local_2;
            i = _e175;
            let _e177 = i[2u];
            if (_e177 > 0f) {
                let _e179 = o;
                let _e180 = i;
                h = normalize((_e179 + _e180));
                let _e183 = o;
                param_17 = _e183;
                let _e184 = h;
                param_18 = _e184;
                let _e186 = (*l_5).alpha;
                param_19 = _e186;
                let _e187 = mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_17), (&param_18), (&param_19));
                let _e188 = o;
                let _e189 = h;
                p = (_e187 / (4f * max(dot(_e188, _e189), 0.000001f)));
                let _e195 = (*l_5).kind;
                if (_e195 == 2i) {
                    let _e197 = p;
                    return _e197;
                }
                let _e199 = (*l_5).mode;
                if ((_e199 & 1i) == 0i) {
                    return 0f;
                }
                let _e202 = o;
                let _e203 = h;
                let _e206 = (*l_5);
                param_20 = _e206;
                param_21 = max(dot(_e202, _e203), 0f);
                let _e207 = above_2;
                param_22 = _e207;
                let _e208 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_20), (&param_21), (&param_22));
                param_23 = _e208;
                let _e209 = mxc_mean_u0028_vf3_u003b((&param_23));
                fr = _e209;
                let _e210 = p;
                let _e211 = (*l_5);
                param_24 = _e211;
                let _e212 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_24));
                phi_2799_ = _e212;
                if _e212 {
                    let _e214 = (*l_5).mode;
                    phi_2799_ = ((_e214 & 1i) != 0i);
                }
                let _e218 = phi_2799_;
                let _e219 = fr;
                return (_e210 * select(1f, _e219, _e218));
            }
            return 0f;
        }
        default: {
            let _e149 = (*wo_1)[2u];
            let _e150 = (_e149 > 0f);
            phi_2718_ = _e150;
            if _e150 {
                let _e152 = (*wi)[2u];
                phi_2718_ = (_e152 > 0f);
            }
            let _e155 = phi_2718_;
            if _e155 {
                let _e157 = (*wi)[2u];
                local_3 = (_e157 * 0.31830987f);
            } else {
                local_3 = 0f;
            }
            let _e159 = local_3;
            return _e159;
        }
    }
}

fn mxc_safe_sqrt_u0028_f1_u003b(x_1: ptr<function, f32>) -> f32 {
    let _e126 = (*x_1);
    return sqrt(max(_e126, 0f));
}

fn mxc_fon_albedo_u0028_f1_u003b_f1_u003b(sigma: ptr<function, f32>, mu_2: ptr<function, f32>) -> f32 {
    var a: f32;
    var c_2: f32;
    var s_1: f32;
    var param_25: f32;
    var theta: f32;
    var tail: f32;
    var local_4: f32;
    var g: f32;

    let _e135 = (*sigma);
    a = (1f / (1f + (0.2877934f * _e135)));
    let _e139 = (*mu_2);
    c_2 = clamp(_e139, 0f, 1f);
    let _e141 = c_2;
    let _e142 = c_2;
    param_25 = (1f - (_e141 * _e142));
    let _e145 = mxc_safe_sqrt_u0028_f1_u003b((&param_25));
    s_1 = _e145;
    let _e146 = c_2;
    theta = acos(_e146);
    let _e148 = c_2;
    if (_e148 > 0.0001f) {
        let _e150 = s_1;
        let _e151 = s_1;
        let _e153 = s_1;
        let _e156 = c_2;
        local_4 = ((1f - ((_e150 * _e151) * _e153)) / _e156);
    } else {
        let _e158 = c_2;
        local_4 = (1.5f * _e158);
    }
    let _e160 = local_4;
    tail = _e160;
    let _e161 = s_1;
    let _e162 = theta;
    let _e163 = s_1;
    let _e164 = c_2;
    let _e168 = s_1;
    let _e170 = tail;
    let _e173 = s_1;
    g = (((_e161 * (_e162 - (_e163 * _e164))) + ((0.6666667f * _e168) * _e170)) - (0.6666667f * _e173));
    let _e176 = a;
    let _e177 = (*sigma);
    let _e178 = a;
    let _e180 = g;
    return (_e176 + (((_e177 * _e178) * _e180) * 0.31830987f));
}

fn mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b(sigma_1: ptr<function, f32>, wo_2: ptr<function, vec3<f32>>, wi_1: ptr<function, vec3<f32>>) -> f32 {
    var a_1: f32;
    var s_2: f32;
    var t: f32;
    var local_5: f32;

    let _e132 = (*sigma_1);
    a_1 = (1f / (1f + (0.2877934f * _e132)));
    let _e136 = (*wi_1);
    let _e137 = (*wo_2);
    let _e140 = (*wi_1)[2u];
    let _e142 = (*wo_2)[2u];
    s_2 = (dot(_e136, _e137) - (_e140 * _e142));
    let _e145 = s_2;
    if (_e145 > 0f) {
        let _e148 = (*wi_1)[2u];
        let _e150 = (*wo_2)[2u];
        local_5 = max(max(_e148, _e150), 0.000001f);
    } else {
        local_5 = 1f;
    }
    let _e153 = local_5;
    t = _e153;
    let _e154 = a_1;
    let _e155 = (*sigma_1);
    let _e156 = a_1;
    let _e158 = s_2;
    let _e160 = t;
    return ((_e154 + (((_e155 * _e156) * _e158) / _e160)) * 0.31830987f);
}

fn mxc_eon_u0028_vf3_u003b_f1_u003b_vf3_u003b_vf3_u003b(rho: ptr<function, vec3<f32>>, sigma_2: ptr<function, f32>, wo_3: ptr<function, vec3<f32>>, wi_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var f_1: vec3<f32>;
    var param_26: f32;
    var param_27: vec3<f32>;
    var param_28: vec3<f32>;
    var a_2: f32;
    var eavg: f32;
    var rhoMs: vec3<f32>;
    var param_29: f32;
    var param_30: f32;
    var param_31: f32;
    var param_32: f32;

    let _e140 = (*rho);
    let _e141 = (*sigma_2);
    param_26 = _e141;
    let _e142 = (*wo_3);
    param_27 = _e142;
    let _e143 = (*wi_2);
    param_28 = _e143;
    let _e144 = mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b((&param_26), (&param_27), (&param_28));
    f_1 = (_e140 * _e144);
    let _e146 = (*sigma_2);
    a_2 = (1f / (1f + (0.2877934f * _e146)));
    let _e150 = a_2;
    let _e151 = (*sigma_2);
    eavg = (_e150 * (1f + (0.07248821f * _e151)));
    let _e155 = eavg;
    if (_e155 < 0.999999f) {
        let _e157 = (*rho);
        let _e158 = (*rho);
        let _e160 = eavg;
        let _e162 = eavg;
        let _e166 = (*rho);
        let _e167 = eavg;
        rhoMs = ((((_e157 * _e158) * _e160) / vec3((1f - _e162))) / (vec3(1f) - (_e166 * (1f - _e167))));
        let _e173 = rhoMs;
        let _e174 = (*sigma_2);
        param_29 = _e174;
        let _e176 = (*wi_2)[2u];
        param_30 = _e176;
        let _e177 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_29), (&param_30));
        let _e180 = (*sigma_2);
        param_31 = _e180;
        let _e182 = (*wo_3)[2u];
        param_32 = _e182;
        let _e183 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_31), (&param_32));
        let _e187 = f_1;
        f_1 = (_e187 + (((_e173 * (1f - _e177)) * (1f - _e183)) * 0.31830987f));
    }
    let _e189 = f_1;
    return _e189;
}

fn mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo_4: ptr<function, vec3<f32>>, wi_3: ptr<function, vec3<f32>>, alpha_6: ptr<function, vec2<f32>>) -> f32 {
    var param_33: vec3<f32>;
    var param_34: vec2<f32>;
    var param_35: vec3<f32>;
    var param_36: vec2<f32>;

    let _e132 = (*wo_4);
    param_33 = _e132;
    let _e133 = (*alpha_6);
    param_34 = _e133;
    let _e134 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_33), (&param_34));
    let _e136 = (*wi_3);
    param_35 = _e136;
    let _e137 = (*alpha_6);
    param_36 = _e137;
    let _e138 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_35), (&param_36));
    return (1f / ((1f + _e134) + _e138));
}

fn mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_6: ptr<function, MxcLobe>, wo_5: ptr<function, vec3<f32>>, wi_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_37: vec2<f32>;
    var h_1: vec3<f32>;
    var f_2: vec3<f32>;
    var param_38: MxcLobe;
    var param_39: f32;
    var param_40: bool;
    var param_41: vec3<f32>;
    var param_42: vec2<f32>;
    var param_43: vec3<f32>;
    var param_44: vec3<f32>;
    var param_45: vec2<f32>;
    var phi_1829_: bool;
    var phi_1836_: bool;

    let _e140 = (*wo_5)[2u];
    let _e141 = (_e140 <= 0f);
    phi_1829_ = _e141;
    if !(_e141) {
        let _e144 = (*wi_4)[2u];
        phi_1829_ = (_e144 <= 0f);
    }
    let _e147 = phi_1829_;
    phi_1836_ = _e147;
    if !(_e147) {
        let _e150 = (*l_6).alpha;
        param_37 = _e150;
        let _e151 = mxc_is_delta_u0028_vf2_u003b((&param_37));
        phi_1836_ = _e151;
    }
    let _e153 = phi_1836_;
    if _e153 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e154 = (*wo_5);
    let _e155 = (*wi_4);
    h_1 = normalize((_e154 + _e155));
    let _e158 = (*wo_5);
    let _e159 = h_1;
    let _e162 = (*l_6);
    param_38 = _e162;
    param_39 = max(dot(_e158, _e159), 0f);
    param_40 = true;
    let _e163 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_38), (&param_39), (&param_40));
    f_2 = _e163;
    let _e165 = (*l_6).kind;
    if (_e165 == 1i) {
        let _e168 = (*l_6).c0_;
        let _e169 = f_2;
        f_2 = (_e169 * _e168);
    }
    let _e171 = f_2;
    let _e172 = h_1;
    param_41 = _e172;
    let _e174 = (*l_6).alpha;
    param_42 = _e174;
    let _e175 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_41), (&param_42));
    let _e177 = (*wo_5);
    param_43 = _e177;
    let _e178 = (*wi_4);
    param_44 = _e178;
    let _e180 = (*l_6).alpha;
    param_45 = _e180;
    let _e181 = mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_43), (&param_44), (&param_45));
    let _e184 = (*wo_5)[2u];
    return (((_e171 * _e175) * _e181) / vec3((4f * _e184)));
}

fn mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_7: ptr<function, MxcLobe>, wo_6: ptr<function, vec3<f32>>, wi_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var m_2: MxcLobe;
    var param_46: MxcLobe;
    var param_47: vec3<f32>;
    var param_48: vec3<f32>;
    var param_49: MxcLobe;
    var param_50: vec3<f32>;
    var param_51: vec3<f32>;
    var param_52: MxcLobe;
    var param_53: vec3<f32>;
    var param_54: vec3<f32>;
    var local_6: vec3<f32>;
    var param_55: vec3<f32>;
    var param_56: f32;
    var param_57: vec3<f32>;
    var param_58: vec3<f32>;
    var phi_2652_: bool;
    var phi_2667_: bool;

    let _e144 = (*l_7).kind;
    switch _e144 {
        case 1: {
            let _e146 = (*wo_6)[2u];
            let _e148 = (*wi_5)[2u];
            if ((_e146 * _e148) > 0f) {
                let _e152 = (*l_7).mode;
                if ((_e152 & 1i) == 0i) {
                    return vec3<f32>(0f, 0f, 0f);
                }
                let _e156 = (*wo_6)[2u];
                if (_e156 < 0f) {
                    let _e158 = (*l_7);
                    m_2 = _e158;
                    let _e160 = (*l_7).eta;
                    m_2.eta = (1f / _e160);
                    m_2.c0_ = vec3<f32>(1f, 1f, 1f);
                    let _e164 = (*wo_6);
                    let _e166 = (*wi_5);
                    let _e168 = m_2;
                    param_46 = _e168;
                    param_47 = -(_e164);
                    param_48 = -(_e166);
                    let _e169 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_46), (&param_47), (&param_48));
                    return _e169;
                }
                let _e170 = (*l_7);
                param_49 = _e170;
                let _e171 = (*wo_6);
                param_50 = _e171;
                let _e172 = (*wi_5);
                param_51 = _e172;
                let _e173 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_49), (&param_50), (&param_51));
                return _e173;
            }
            return vec3<f32>(0f, 0f, 0f);
        }
        case 3, 2: {
            let _e175 = (*l_7).kind;
            let _e176 = (_e175 == 3i);
            phi_2652_ = _e176;
            if _e176 {
                let _e178 = (*l_7).mode;
                phi_2652_ = ((_e178 & 1i) == 0i);
            }
            let _e182 = phi_2652_;
            if _e182 {
                return vec3<f32>(0f, 0f, 0f);
            }
            let _e183 = (*l_7);
            param_52 = _e183;
            let _e184 = (*wo_6);
            param_53 = _e184;
            let _e185 = (*wi_5);
            param_54 = _e185;
            let _e186 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_52), (&param_53), (&param_54));
            return _e186;
        }
        case 5: {
            let _e188 = (*wo_6)[2u];
            let _e189 = (_e188 > 0f);
            phi_2667_ = _e189;
            if _e189 {
                let _e191 = (*wi_5)[2u];
                phi_2667_ = (_e191 > 0f);
            }
            let _e194 = phi_2667_;
            if _e194 {
                let _e196 = (*l_7).c0_;
                param_55 = _e196;
                let _e198 = (*l_7).p0_;
                param_56 = _e198;
                let _e199 = (*wo_6);
                param_57 = _e199;
                let _e200 = (*wi_5);
                param_58 = _e200;
                let _e201 = mxc_eon_u0028_vf3_u003b_f1_u003b_vf3_u003b_vf3_u003b((&param_55), (&param_56), (&param_57), (&param_58));
                let _e203 = (*wi_5)[2u];
                local_6 = (_e201 * _e203);
            } else {
                local_6 = vec3<f32>(0f, 0f, 0f);
            }
            let _e205 = local_6;
            return _e205;
        }
        default: {
            return vec3<f32>(0f, 0f, 0f);
        }
    }
}

fn mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_8: ptr<function, MxcLobe>, transmitted: ptr<function, bool>) -> MxcLobe {
    var m_3: MxcLobe;
    var local_7: i32;

    let _e129 = (*l_8);
    m_3 = _e129;
    let _e131 = (*l_8).alpha;
    let _e132 = (*transmitted);
    m_3.alpha = min((_e131 * select(1.5f, 3f, _e132)), vec2<f32>(1f, 1f));
    let _e137 = (*transmitted);
    if _e137 {
        let _e139 = (*l_8).mode;
        local_7 = (_e139 & -2i);
    } else {
        let _e142 = (*l_8).mode;
        local_7 = (_e142 & -3i);
    }
    let _e144 = local_7;
    m_3.mode = _e144;
    let _e147 = (*l_8).kind;
    if (_e147 == 1i) {
        m_3.c0_ = vec3<f32>(1f, 1f, 1f);
        m_3.c1_ = vec3<f32>(1f, 1f, 1f);
    }
    let _e151 = m_3;
    return _e151;
}

fn mxc_to_local_u0028_mf33_u003b_vf3_u003b(frame: ptr<function, mat3x3<f32>>, v_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e127 = (*v_2);
    let _e129 = (*frame)[0];
    let _e131 = (*v_2);
    let _e133 = (*frame)[1];
    let _e135 = (*v_2);
    let _e137 = (*frame)[2];
    return vec3<f32>(dot(_e127, _e129), dot(_e131, _e133), dot(_e135, _e137));
}

fn mxc_frame_u0028_vf3_u003b_vf3_u003b(N: ptr<function, vec3<f32>>, T: ptr<function, vec3<f32>>) -> mat3x3<f32> {
    var t_1: vec3<f32>;
    var l2_: f32;
    var s_3: f32;
    var a_3: f32;
    var b: f32;

    let _e132 = (*T);
    let _e133 = (*N);
    let _e134 = (*N);
    let _e135 = (*T);
    t_1 = (_e132 - (_e133 * dot(_e134, _e135)));
    let _e139 = t_1;
    let _e140 = t_1;
    l2_ = dot(_e139, _e140);
    let _e142 = l2_;
    if !((_e142 > 0.000000000001f)) {
        let _e146 = (*N)[2u];
        s_3 = select(-1f, 1f, (_e146 >= 0f));
        let _e149 = s_3;
        let _e151 = (*N)[2u];
        a_3 = (-1f / (_e149 + _e151));
        let _e155 = (*N)[0u];
        let _e157 = (*N)[1u];
        let _e159 = a_3;
        b = ((_e155 * _e157) * _e159);
        let _e161 = s_3;
        let _e163 = (*N)[0u];
        let _e166 = (*N)[0u];
        let _e168 = a_3;
        let _e171 = s_3;
        let _e172 = b;
        let _e174 = s_3;
        let _e177 = (*N)[0u];
        t_1 = vec3<f32>((1f + (((_e161 * _e163) * _e166) * _e168)), (_e171 * _e172), (-(_e174) * _e177));
    } else {
        let _e180 = l2_;
        let _e182 = t_1;
        t_1 = (_e182 * inverseSqrt(_e180));
    }
    let _e184 = t_1;
    let _e185 = (*N);
    let _e186 = t_1;
    let _e187 = cross(_e185, _e186);
    let _e188 = (*N);
    return mat3x3<f32>(vec3<f32>(_e184.x, _e184.y, _e184.z), vec3<f32>(_e187.x, _e187.y, _e187.z), vec3<f32>(_e188.x, _e188.y, _e188.z));
}

fn mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b(c_3: ptr<function, MxcClosure>, wo_7: ptr<function, vec3<f32>>, wi_6: ptr<function, vec3<f32>>, wantPdf: ptr<function, bool>, pdf: ptr<function, f32>) -> vec3<f32> {
    var f_3: vec3<f32>;
    var p_1: f32;
    var k: i32;
    var l_9: MxcLobe;
    var frame_1: mat3x3<f32>;
    var param_59: vec3<f32>;
    var param_60: vec3<f32>;
    var o_1: vec3<f32>;
    var param_61: mat3x3<f32>;
    var param_62: vec3<f32>;
    var i_1: vec3<f32>;
    var param_63: mat3x3<f32>;
    var param_64: vec3<f32>;
    var fk: vec3<f32>;
    var pk: f32;
    var passes: i32;
    var pass_: i32;
    var shaped: bool;
    var m_4: MxcLobe;
    var local_8: MxcLobe;
    var param_65: MxcLobe;
    var param_66: bool;
    var scale: vec3<f32>;
    var local_9: vec3<f32>;
    var local_10: vec3<f32>;
    var local_11: vec3<f32>;
    var param_67: MxcLobe;
    var param_68: vec3<f32>;
    var param_69: vec3<f32>;
    var share: f32;
    var local_12: f32;
    var local_13: f32;
    var param_70: MxcLobe;
    var param_71: vec3<f32>;
    var param_72: vec3<f32>;
    var param_73: MxcLobe;
    var param_74: f32;
    var local_14: f32;

    f_3 = vec3<f32>(0f, 0f, 0f);
    p_1 = 0f;
    k = 0i;
    loop {
        let _e168 = k;
        let _e170 = (*c_3).count;
        if (_e168 < _e170) {
            let _e172 = k;
            let _e175 = (*c_3).lobes[_e172];
            l_9 = _e175;
            let _e177 = l_9.weight;
            if all((_e177 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e181 = l_9.N;
            param_59 = _e181;
            let _e183 = l_9.T;
            param_60 = _e183;
            let _e184 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_59), (&param_60));
            frame_1 = _e184;
            let _e185 = frame_1;
            param_61 = _e185;
            let _e186 = (*wo_7);
            param_62 = _e186;
            let _e187 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_61), (&param_62));
            o_1 = _e187;
            let _e188 = frame_1;
            param_63 = _e188;
            let _e189 = (*wi_6);
            param_64 = _e189;
            let _e190 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_63), (&param_64));
            i_1 = _e190;
            fk = vec3<f32>(0f, 0f, 0f);
            pk = 0f;
            let _e191 = k;
            let _e194 = (*c_3).msPick[_e191];
            passes = select(1i, 2i, (_e194 > 0f));
            pass_ = 0i;
            loop {
                let _e197 = pass_;
                let _e198 = passes;
                if (_e197 < _e198) {
                    let _e200 = pass_;
                    shaped = (_e200 == 1i);
                    let _e202 = shaped;
                    if _e202 {
                        let _e204 = i_1[2u];
                        let _e206 = l_9;
                        param_65 = _e206;
                        param_66 = (_e204 < 0f);
                        let _e207 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_65), (&param_66));
                        local_8 = _e207;
                    } else {
                        let _e208 = l_9;
                        local_8 = _e208;
                    }
                    let _e209 = local_8;
                    m_4 = _e209;
                    let _e210 = shaped;
                    if _e210 {
                        let _e212 = i_1[2u];
                        if (_e212 > 0f) {
                            let _e214 = k;
                            let _e217 = (*c_3).msLobe[_e214];
                            local_10 = _e217;
                        } else {
                            let _e218 = k;
                            let _e221 = (*c_3).msLobeT[_e218];
                            local_10 = _e221;
                        }
                        let _e222 = local_10;
                        local_9 = _e222;
                    } else {
                        let _e224 = o_1[2u];
                        let _e226 = i_1[2u];
                        if ((_e224 * _e226) < 0f) {
                            let _e229 = k;
                            let _e232 = (*c_3).msT[_e229];
                            local_11 = vec3(_e232);
                        } else {
                            let _e234 = k;
                            let _e237 = (*c_3).ms[_e234];
                            local_11 = _e237;
                        }
                        let _e238 = local_11;
                        local_9 = _e238;
                    }
                    let _e239 = local_9;
                    scale = _e239;
                    let _e240 = scale;
                    let _e241 = m_4;
                    param_67 = _e241;
                    let _e242 = o_1;
                    param_68 = _e242;
                    let _e243 = i_1;
                    param_69 = _e243;
                    let _e244 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_67), (&param_68), (&param_69));
                    let _e246 = fk;
                    fk = (_e246 + (_e240 * _e244));
                    let _e248 = (*wantPdf);
                    if _e248 {
                        let _e249 = shaped;
                        if _e249 {
                            let _e250 = k;
                            let _e253 = (*c_3).msPick[_e250];
                            let _e255 = i_1[2u];
                            if (_e255 > 0f) {
                                let _e257 = k;
                                let _e260 = (*c_3).msSplit[_e257];
                                local_13 = _e260;
                            } else {
                                let _e261 = k;
                                let _e264 = (*c_3).msSplit[_e261];
                                local_13 = (1f - _e264);
                            }
                            let _e266 = local_13;
                            local_12 = (_e253 * _e266);
                        } else {
                            let _e268 = k;
                            let _e271 = (*c_3).msPick[_e268];
                            local_12 = (1f - _e271);
                        }
                        let _e273 = local_12;
                        share = _e273;
                        let _e274 = share;
                        let _e275 = m_4;
                        param_70 = _e275;
                        let _e276 = o_1;
                        param_71 = _e276;
                        let _e277 = i_1;
                        param_72 = _e277;
                        let _e278 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_70), (&param_71), (&param_72));
                        let _e280 = pk;
                        pk = (_e280 + (_e274 * _e278));
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e282 = pass_;
                    pass_ = (_e282 + 1i);
                }
            }
            let _e285 = l_9.weight;
            let _e287 = i_1[2u];
            let _e289 = l_9;
            param_73 = _e289;
            param_74 = abs(_e287);
            let _e290 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_73), (&param_74));
            let _e292 = fk;
            let _e294 = f_3;
            f_3 = (_e294 + ((_e285 * _e290) * _e292));
            let _e296 = (*wantPdf);
            if _e296 {
                let _e297 = k;
                let _e300 = (*c_3).choice[_e297];
                let _e301 = pk;
                let _e303 = p_1;
                p_1 = (_e303 + (_e300 * _e301));
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e305 = k;
            k = (_e305 + 1i);
        }
    }
    let _e308 = (*c_3).choiceTotal;
    if (_e308 > 0f) {
        let _e310 = p_1;
        let _e312 = (*c_3).choiceTotal;
        local_14 = (_e310 / _e312);
    } else {
        local_14 = 0f;
    }
    let _e314 = local_14;
    (*pdf) = _e314;
    let _e315 = f_3;
    return _e315;
}

fn mxc_env_to_world_u0028_vf3_u003b_f1_u003b(m_5: ptr<function, vec3<f32>>, angle: ptr<function, f32>) -> vec3<f32> {
    var c_4: f32;
    var s_4: f32;

    let _e129 = (*angle);
    c_4 = cos(_e129);
    let _e131 = (*angle);
    s_4 = sin(_e131);
    let _e133 = c_4;
    let _e135 = (*m_5)[0u];
    let _e137 = s_4;
    let _e139 = (*m_5)[2u];
    let _e143 = (*m_5)[1u];
    let _e144 = s_4;
    let _e147 = (*m_5)[0u];
    let _e149 = c_4;
    let _e151 = (*m_5)[2u];
    return vec3<f32>(((_e133 * _e135) + (_e137 * _e139)), _e143, ((-(_e144) * _e147) + (_e149 * _e151)));
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
    var param_75: f32;

    let _e140 = unnamed.mxc_env_size;
    size = max(_e140.xy, vec2<u32>(1u, 1u));
    let _e144 = size[0u];
    let _e146 = size[1u];
    n = (_e144 * _e146);
    let _e149 = (*u)[0u];
    let _e150 = n;
    let _e154 = n;
    k_1 = min(u32((_e149 * f32(_e150))), (_e154 - 1u));
    let _e157 = k_1;
    let _e160 = unnamed.mxc_env_cells[_e157];
    cell = _e160;
    let _e162 = (*u)[1u];
    let _e164 = cell[0u];
    if (_e162 >= _e164) {
        let _e167 = cell[1u];
        let _e169 = n;
        k_1 = min(bitcast<u32>(_e167), (_e169 - 1u));
    }
    let _e172 = k_1;
    let _e176 = unnamed.mxc_env_cells[_e172][2u];
    (*pdf_1) = _e176;
    let _e177 = k_1;
    let _e179 = size[0u];
    i_2 = (_e177 % _e179);
    let _e181 = k_1;
    let _e183 = size[0u];
    j = (_e181 / _e183);
    let _e185 = i_2;
    let _e188 = (*u)[2u];
    let _e191 = size[0u];
    phi = (6.2831855f * (((f32(_e185) + _e188) / f32(_e191)) - 0.5f));
    let _e196 = j;
    let _e200 = size[1u];
    y0_ = cos(((3.1415927f * f32(_e196)) / f32(_e200)));
    let _e204 = j;
    let _e209 = size[1u];
    y1_ = cos(((3.1415927f * f32((_e204 + 1u))) / f32(_e209)));
    let _e213 = y0_;
    let _e214 = y1_;
    let _e216 = (*u)[3u];
    y = mix(_e213, _e214, _e216);
    let _e218 = y;
    let _e219 = y;
    param_75 = (1f - (_e218 * _e219));
    let _e222 = mxc_safe_sqrt_u0028_f1_u003b((&param_75));
    r = _e222;
    let _e223 = r;
    let _e224 = phi;
    let _e227 = y;
    let _e228 = r;
    let _e230 = phi;
    return vec3<f32>((_e223 * sin(_e224)), _e227, (-(_e228) * cos(_e230)));
}

fn mxc_power_heuristic_u0028_f1_u003b_f1_u003b(a_4: ptr<function, f32>, b_1: ptr<function, f32>) -> f32 {
    var a2_1: f32;
    var b2_: f32;
    var local_15: f32;

    let _e130 = (*a_4);
    let _e131 = (*a_4);
    a2_1 = (_e130 * _e131);
    let _e133 = (*b_1);
    let _e134 = (*b_1);
    b2_ = (_e133 * _e134);
    let _e136 = a2_1;
    let _e137 = b2_;
    if ((_e136 + _e137) > 0f) {
        let _e140 = a2_1;
        let _e141 = a2_1;
        let _e142 = b2_;
        local_15 = (_e140 / (_e141 + _e142));
    } else {
        local_15 = 0f;
    }
    let _e145 = local_15;
    return _e145;
}

fn mxc_env_uv_u0028_vf3_u003b(d_1: ptr<function, vec3<f32>>) -> vec2<f32> {
    var u_1: f32;
    var local_16: f32;
    var v_3: f32;

    let _e130 = (*d_1)[0u];
    let _e133 = (*d_1)[2u];
    if ((abs(_e130) + abs(_e133)) > 0.000000000001f) {
        let _e138 = (*d_1)[0u];
        let _e140 = (*d_1)[2u];
        local_16 = (0.5f + (atan2(_e138, -(_e140)) * 0.15915494f));
    } else {
        local_16 = 0.5f;
    }
    let _e145 = local_16;
    u_1 = _e145;
    let _e146 = (*d_1);
    let _e150 = (*d_1)[1u];
    v_3 = (atan2(length(_e146.xz), _e150) * 0.31830987f);
    let _e153 = u_1;
    let _e154 = v_3;
    return vec2<f32>(_e153, _e154);
}

fn mxc_env_cell_u0028_vf3_u003b(d_2: ptr<function, vec3<f32>>) -> u32 {
    var uv: vec2<f32>;
    var param_76: vec3<f32>;
    var size_1: vec2<u32>;
    var i_3: u32;
    var j_1: u32;

    let _e131 = (*d_2);
    param_76 = _e131;
    let _e132 = mxc_env_uv_u0028_vf3_u003b((&param_76));
    uv = _e132;
    let _e134 = unnamed.mxc_env_size;
    size_1 = max(_e134.xy, vec2<u32>(1u, 1u));
    let _e138 = uv[0u];
    let _e141 = size_1[0u];
    let _e146 = size_1[0u];
    i_3 = min(u32((max(_e138, 0f) * f32(_e141))), (_e146 - 1u));
    let _e150 = uv[1u];
    let _e153 = size_1[1u];
    let _e158 = size_1[1u];
    j_1 = min(u32((max(_e150, 0f) * f32(_e153))), (_e158 - 1u));
    let _e161 = j_1;
    let _e163 = size_1[0u];
    let _e165 = i_3;
    return ((_e161 * _e163) + _e165);
}

fn mxc_env_pdf_u0028_vf3_u003b(d_3: ptr<function, vec3<f32>>) -> f32 {
    var param_77: vec3<f32>;

    let _e127 = (*d_3);
    param_77 = _e127;
    let _e128 = mxc_env_cell_u0028_vf3_u003b((&param_77));
    let _e132 = unnamed.mxc_env_cells[_e128][2u];
    return _e132;
}

fn mxc_env_to_map_u0028_vf3_u003b_f1_u003b(w: ptr<function, vec3<f32>>, angle_1: ptr<function, f32>) -> vec3<f32> {
    var c_5: f32;
    var s_5: f32;

    let _e129 = (*angle_1);
    c_5 = cos(_e129);
    let _e131 = (*angle_1);
    s_5 = sin(_e131);
    let _e133 = c_5;
    let _e135 = (*w)[0u];
    let _e137 = s_5;
    let _e139 = (*w)[2u];
    let _e143 = (*w)[1u];
    let _e144 = s_5;
    let _e146 = (*w)[0u];
    let _e148 = c_5;
    let _e150 = (*w)[2u];
    return vec3<f32>(((_e133 * _e135) - (_e137 * _e139)), _e143, ((_e144 * _e146) + (_e148 * _e150)));
}

fn mxc_env_lookup_u0028_vf3_u003b(d_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_78: vec3<f32>;

    let _e127 = (*d_4);
    param_78 = _e127;
    let _e128 = mxc_env_uv_u0028_vf3_u003b((&param_78));
    let _e129 = textureSampleLevel(mxc_env_radiance_texture, mxc_env_radiance_sampler, _e128, 0f);
    return _e129.xyz;
}

fn mxc_sky_u0028_vf3_u003b(d_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var y_1: f32;
    var horizon: vec3<f32>;
    var zenith: vec3<f32>;
    var ground: vec3<f32>;

    let _e131 = (*d_5)[1u];
    y_1 = clamp(_e131, -1f, 1f);
    horizon = vec3<f32>(1f, 0.96f, 0.9f);
    zenith = vec3<f32>(0.3f, 0.5f, 0.95f);
    ground = vec3<f32>(0.16f, 0.145f, 0.13f);
    let _e133 = y_1;
    if (_e133 >= 0f) {
        let _e135 = horizon;
        let _e136 = zenith;
        let _e137 = y_1;
        return mix(_e135, _e136, vec3(sqrt(_e137)));
    }
    let _e141 = horizon;
    let _e142 = ground;
    let _e143 = y_1;
    return mix(_e141, _e142, vec3(sqrt(-(_e143))));
}

fn mxc_environment_code_u0028_() -> i32 {
    var local_17: i32;

    if false {
        local_17 = MXC_ENVIRONMENT;
    } else {
        let _e128 = mxc_view.counts[1u];
        local_17 = _e128;
    }
    let _e129 = local_17;
    return _e129;
}

fn mxc_environment_u0028_vf3_u003b(d_6: ptr<function, vec3<f32>>) -> vec3<f32> {
    var code: i32;
    var param_79: vec3<f32>;
    var param_80: vec3<f32>;
    var param_81: f32;
    var param_82: vec3<f32>;

    let _e131 = mxc_environment_code_u0028_();
    code = _e131;
    let _e132 = code;
    if (_e132 == 1i) {
        let _e136 = mxc_view.environment[0u];
        return vec3(_e136);
    }
    let _e138 = code;
    if (_e138 == 2i) {
        let _e142 = mxc_view.environment[0u];
        let _e143 = (*d_6);
        param_79 = _e143;
        let _e144 = mxc_sky_u0028_vf3_u003b((&param_79));
        return (_e144 * _e142);
    }
    let _e146 = code;
    if (_e146 == 3i) {
        let _e150 = mxc_view.environment[0u];
        let _e151 = (*d_6);
        param_80 = _e151;
        let _e154 = mxc_view.environment[2u];
        param_81 = _e154;
        let _e155 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_80), (&param_81));
        param_82 = _e155;
        let _e156 = mxc_env_lookup_u0028_vf3_u003b((&param_82));
        return (_e156 * _e150);
    }
    return vec3<f32>(0f, 0f, 0f);
}

fn mxc_exit_direction_u0028_vf3_u003b_vf3_u003b(d_7: ptr<function, vec3<f32>>, t_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var axis: vec3<f32>;
    var s_6: f32;
    var c_6: f32;

    let _e130 = (*d_7);
    let _e131 = (*t_2);
    axis = cross(_e130, _e131);
    let _e133 = axis;
    s_6 = length(_e133);
    let _e135 = s_6;
    if (_e135 < 0.000001f) {
        let _e137 = (*t_2);
        return _e137;
    }
    let _e138 = s_6;
    let _e139 = axis;
    axis = (_e139 / vec3(_e138));
    let _e142 = (*d_7);
    let _e143 = (*t_2);
    c_6 = dot(_e142, _e143);
    let _e145 = (*t_2);
    let _e146 = c_6;
    let _e148 = axis;
    let _e149 = (*t_2);
    let _e151 = s_6;
    let _e154 = axis;
    let _e155 = axis;
    let _e156 = (*t_2);
    let _e159 = c_6;
    return (((_e145 * _e146) + (cross(_e148, _e149) * _e151)) + ((_e154 * dot(_e155, _e156)) * (1f - _e159)));
}

fn mxc_to_world_u0028_mf33_u003b_vf3_u003b(frame_2: ptr<function, mat3x3<f32>>, v_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e128 = (*frame_2)[0];
    let _e130 = (*v_4)[0u];
    let _e133 = (*frame_2)[1];
    let _e135 = (*v_4)[1u];
    let _e139 = (*frame_2)[2];
    let _e141 = (*v_4)[2u];
    return (((_e128 * _e130) + (_e133 * _e135)) + (_e139 * _e141));
}

fn mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b(wo_8: ptr<function, vec3<f32>>, alpha_7: ptr<function, vec2<f32>>, u_2: ptr<function, vec2<f32>>) -> vec3<f32> {
    var param_83: vec2<f32>;
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
    var param_84: f32;
    var nh: vec3<f32>;
    var param_85: f32;

    let _e142 = (*alpha_7);
    param_83 = _e142;
    let _e143 = mxc_rough_alpha_u0028_vf2_u003b((&param_83));
    (*alpha_7) = _e143;
    let _e145 = (*alpha_7)[0u];
    let _e147 = (*wo_8)[0u];
    let _e150 = (*alpha_7)[1u];
    let _e152 = (*wo_8)[1u];
    let _e155 = (*wo_8)[2u];
    vh = normalize(vec3<f32>((_e145 * _e147), (_e150 * _e152), _e155));
    let _e159 = vh[0u];
    let _e161 = vh[0u];
    let _e164 = vh[1u];
    let _e166 = vh[1u];
    lensq = ((_e159 * _e161) + (_e164 * _e166));
    let _e169 = lensq;
    if (_e169 > 0f) {
        let _e172 = vh[1u];
        let _e175 = vh[0u];
        let _e177 = lensq;
        local_18 = (vec3<f32>(-(_e172), _e175, 0f) * inverseSqrt(_e177));
    } else {
        local_18 = vec3<f32>(1f, 0f, 0f);
    }
    let _e180 = local_18;
    t1_ = _e180;
    let _e181 = vh;
    let _e182 = t1_;
    t2_ = cross(_e181, _e182);
    let _e185 = (*u_2)[0u];
    r_1 = sqrt(_e185);
    let _e188 = (*u_2)[1u];
    phi_1 = (6.2831855f * _e188);
    let _e190 = r_1;
    let _e191 = phi_1;
    p1_ = (_e190 * cos(_e191));
    let _e194 = r_1;
    let _e195 = phi_1;
    p2_ = (_e194 * sin(_e195));
    let _e199 = vh[2u];
    s_7 = (0.5f * (1f + _e199));
    let _e202 = s_7;
    let _e204 = p1_;
    let _e205 = p1_;
    param_84 = (1f - (_e204 * _e205));
    let _e208 = mxc_safe_sqrt_u0028_f1_u003b((&param_84));
    let _e210 = s_7;
    let _e211 = p2_;
    p2_ = (((1f - _e202) * _e208) + (_e210 * _e211));
    let _e214 = p1_;
    let _e215 = t1_;
    let _e217 = p2_;
    let _e218 = t2_;
    let _e221 = p1_;
    let _e222 = p1_;
    let _e225 = p2_;
    let _e226 = p2_;
    param_85 = ((1f - (_e221 * _e222)) - (_e225 * _e226));
    let _e229 = mxc_safe_sqrt_u0028_f1_u003b((&param_85));
    let _e230 = vh;
    nh = (((_e215 * _e214) + (_e218 * _e217)) + (_e230 * _e229));
    let _e234 = (*alpha_7)[0u];
    let _e236 = nh[0u];
    let _e239 = (*alpha_7)[1u];
    let _e241 = nh[1u];
    let _e244 = nh[2u];
    return normalize(vec3<f32>((_e234 * _e236), (_e239 * _e241), max(_e244, 0f)));
}

fn mxc_sample_cosine_u0028_vf2_u003b(u_3: ptr<function, vec2<f32>>) -> vec3<f32> {
    var r_2: f32;
    var phi_2: f32;
    var param_86: f32;

    let _e130 = (*u_3)[0u];
    r_2 = sqrt(_e130);
    let _e133 = (*u_3)[1u];
    phi_2 = (6.2831855f * _e133);
    let _e135 = r_2;
    let _e136 = phi_2;
    let _e139 = r_2;
    let _e140 = phi_2;
    let _e144 = (*u_3)[0u];
    param_86 = (1f - _e144);
    let _e146 = mxc_safe_sqrt_u0028_f1_u003b((&param_86));
    return vec3<f32>((_e135 * cos(_e136)), (_e139 * sin(_e140)), _e146);
}

fn mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_10: ptr<function, MxcLobe>, wo_9: ptr<function, vec3<f32>>, u_4: ptr<function, vec3<f32>>) -> MxcLobeSample {
    var s_8: MxcLobeSample;
    var above_3: bool;
    var o_2: vec3<f32>;
    var local_19: vec3<f32>;
    var delta: bool;
    var param_87: vec2<f32>;
    var m_6: vec3<f32>;
    var local_20: vec3<f32>;
    var param_88: vec3<f32>;
    var param_89: vec2<f32>;
    var param_90: vec2<f32>;
    var hm: f32;
    var transmits: bool;
    var param_91: MxcLobe;
    var reflects: bool;
    var f_4: vec3<f32>;
    var param_92: MxcLobe;
    var param_93: f32;
    var param_94: bool;
    var fr_1: f32;
    var local_21: f32;
    var param_95: vec3<f32>;
    var pReflect: f32;
    var local_22: f32;
    var i_4: vec3<f32>;
    var local_23: vec3<f32>;
    var tint: vec3<f32>;
    var local_24: vec3<f32>;
    var local_25: vec3<f32>;
    var param_96: MxcLobe;
    var param_97: vec3<f32>;
    var param_98: vec3<f32>;
    var param_99: MxcLobe;
    var param_100: vec3<f32>;
    var param_101: vec3<f32>;
    var param_102: vec2<f32>;
    var param_103: MxcLobe;
    var param_104: vec3<f32>;
    var param_105: vec3<f32>;
    var param_106: MxcLobe;
    var param_107: vec3<f32>;
    var param_108: vec3<f32>;
    var phi_2930_: bool;
    var phi_2935_: bool;
    var phi_2946_: bool;

    s_8.valid = false;
    s_8.delta = false;
    s_8.pdf = 0f;
    s_8.value = vec3<f32>(0f, 0f, 0f);
    s_8.wi = vec3<f32>(0f, 0f, 1f);
    let _e176 = (*l_10).kind;
    switch _e176 {
        case 2, 3, 1: {
            let _e203 = (*wo_9)[2u];
            above_3 = (_e203 > 0f);
            let _e205 = above_3;
            if _e205 {
                let _e206 = (*wo_9);
                local_19 = _e206;
            } else {
                let _e207 = (*wo_9);
                local_19 = -(_e207);
            }
            let _e209 = local_19;
            o_2 = _e209;
            let _e211 = o_2[2u];
            if (_e211 <= 0f) {
                let _e213 = s_8;
                return _e213;
            }
            let _e215 = (*l_10).alpha;
            param_87 = _e215;
            let _e216 = mxc_is_delta_u0028_vf2_u003b((&param_87));
            delta = _e216;
            let _e217 = delta;
            if _e217 {
                local_20 = vec3<f32>(0f, 0f, 1f);
            } else {
                let _e218 = o_2;
                param_88 = _e218;
                let _e220 = (*l_10).alpha;
                param_89 = _e220;
                let _e221 = (*u_4);
                param_90 = _e221.xy;
                let _e223 = mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b((&param_88), (&param_89), (&param_90));
                local_20 = _e223;
            }
            let _e224 = local_20;
            m_6 = _e224;
            let _e225 = o_2;
            let _e226 = m_6;
            hm = dot(_e225, _e226);
            let _e229 = (*l_10).kind;
            let _e230 = (_e229 == 1i);
            phi_2930_ = _e230;
            if !(_e230) {
                let _e233 = (*l_10).kind;
                phi_2930_ = (_e233 == 3i);
            }
            let _e236 = phi_2930_;
            phi_2935_ = _e236;
            if _e236 {
                let _e237 = (*l_10);
                param_91 = _e237;
                let _e238 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_91));
                phi_2935_ = _e238;
            }
            let _e240 = phi_2935_;
            transmits = _e240;
            let _e242 = (*l_10).kind;
            let _e243 = (_e242 == 2i);
            phi_2946_ = _e243;
            if !(_e243) {
                let _e246 = (*l_10).mode;
                phi_2946_ = ((_e246 & 1i) != 0i);
            }
            let _e250 = phi_2946_;
            reflects = _e250;
            let _e251 = hm;
            let _e253 = (*l_10);
            param_92 = _e253;
            param_93 = max(_e251, 0f);
            let _e254 = above_3;
            param_94 = _e254;
            let _e255 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_92), (&param_93), (&param_94));
            f_4 = _e255;
            let _e256 = transmits;
            if _e256 {
                let _e257 = f_4;
                param_95 = _e257;
                let _e258 = mxc_mean_u0028_vf3_u003b((&param_95));
                local_21 = _e258;
            } else {
                local_21 = 1f;
            }
            let _e259 = local_21;
            fr_1 = _e259;
            let _e260 = transmits;
            if _e260 {
                let _e261 = reflects;
                let _e262 = fr_1;
                local_22 = select(0f, _e262, _e261);
            } else {
                local_22 = 1f;
            }
            let _e264 = local_22;
            pReflect = _e264;
            let _e266 = (*u_4)[2u];
            let _e267 = pReflect;
            if (_e266 < _e267) {
                let _e269 = o_2;
                let _e271 = m_6;
                i_4 = reflect(-(_e269), _e271);
                let _e274 = i_4[2u];
                if (_e274 <= 0f) {
                    let _e276 = s_8;
                    return _e276;
                }
                let _e277 = above_3;
                if _e277 {
                    let _e278 = i_4;
                    local_23 = _e278;
                } else {
                    let _e279 = i_4;
                    local_23 = -(_e279);
                }
                let _e281 = local_23;
                s_8.wi = _e281;
                let _e283 = delta;
                s_8.delta = _e283;
                let _e285 = delta;
                if _e285 {
                    let _e287 = (*l_10).kind;
                    if (_e287 == 1i) {
                        let _e289 = above_3;
                        if _e289 {
                            let _e291 = (*l_10).c0_;
                            local_25 = _e291;
                        } else {
                            local_25 = vec3<f32>(1f, 1f, 1f);
                        }
                        let _e292 = local_25;
                        local_24 = _e292;
                    } else {
                        local_24 = vec3<f32>(1f, 1f, 1f);
                    }
                    let _e293 = local_24;
                    tint = _e293;
                    let _e294 = f_4;
                    let _e295 = tint;
                    s_8.value = (_e294 * _e295);
                    let _e298 = pReflect;
                    s_8.pdf = _e298;
                } else {
                    let _e300 = (*l_10);
                    param_96 = _e300;
                    let _e301 = (*wo_9);
                    param_97 = _e301;
                    let _e303 = s_8.wi;
                    param_98 = _e303;
                    let _e304 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_96), (&param_97), (&param_98));
                    s_8.value = _e304;
                    let _e306 = (*l_10);
                    param_99 = _e306;
                    let _e307 = (*wo_9);
                    param_100 = _e307;
                    let _e309 = s_8.wi;
                    param_101 = _e309;
                    let _e310 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_99), (&param_100), (&param_101));
                    s_8.pdf = _e310;
                }
                let _e313 = s_8.pdf;
                s_8.valid = (_e313 > 0f);
                let _e316 = s_8;
                return _e316;
            }
            let _e317 = s_8;
            return _e317;
        }
        default: {
            let _e178 = (*wo_9)[2u];
            if (_e178 <= 0f) {
                let _e180 = s_8;
                return _e180;
            }
            let _e181 = (*u_4);
            param_102 = _e181.xy;
            let _e183 = mxc_sample_cosine_u0028_vf2_u003b((&param_102));
            s_8.wi = _e183;
            let _e185 = (*l_10);
            param_103 = _e185;
            let _e186 = (*wo_9);
            param_104 = _e186;
            let _e188 = s_8.wi;
            param_105 = _e188;
            let _e189 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_103), (&param_104), (&param_105));
            s_8.value = _e189;
            let _e191 = (*l_10);
            param_106 = _e191;
            let _e192 = (*wo_9);
            param_107 = _e192;
            let _e194 = s_8.wi;
            param_108 = _e194;
            let _e195 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_106), (&param_107), (&param_108));
            s_8.pdf = _e195;
            let _e198 = s_8.pdf;
            s_8.valid = (_e198 > 0f);
            let _e201 = s_8;
            return _e201;
        }
    }
}

fn mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b(c_7: ptr<function, MxcClosure>, wo_10: ptr<function, vec3<f32>>, u_5: ptr<function, vec3<f32>>) -> MxcSample {
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
    var l_11: MxcLobe;
    var frame_3: mat3x3<f32>;
    var param_109: vec3<f32>;
    var param_110: vec3<f32>;
    var o_3: vec3<f32>;
    var param_111: mat3x3<f32>;
    var param_112: vec3<f32>;
    var q: f32;
    var shaped_1: bool;
    var reflected: bool;
    var v_5: f32;
    var split: f32;
    var local_26: f32;
    var m_7: MxcLobe;
    var local_27: MxcLobe;
    var param_113: MxcLobe;
    var param_114: bool;
    var ls: MxcLobeSample;
    var param_115: MxcLobe;
    var param_116: vec3<f32>;
    var param_117: vec3<f32>;
    var param_118: mat3x3<f32>;
    var param_119: vec3<f32>;
    var param_120: MxcLobe;
    var param_121: f32;

    s_9.valid = false;
    s_9.delta = false;
    s_9.evaluate = false;
    s_9.pdf = 0f;
    s_9.weight = vec3<f32>(0f, 0f, 0f);
    let _e169 = (*wo_10);
    s_9.wi = _e169;
    let _e172 = (*c_7).choiceTotal;
    total = _e172;
    let _e174 = (*c_7).count;
    let _e176 = total;
    if ((_e174 == 0i) || (_e176 <= 0f)) {
        let _e179 = s_9;
        return _e179;
    }
    let _e181 = (*u_5)[2u];
    let _e182 = total;
    x_2 = (_e181 * _e182);
    chosen = -1i;
    before = 0f;
    p_2 = 0f;
    lastBefore = 0f;
    last = -1i;
    k_2 = 0i;
    loop {
        let _e184 = k_2;
        let _e186 = (*c_7).count;
        if (_e184 < _e186) {
            let _e188 = k_2;
            let _e191 = (*c_7).choice[_e188];
            pk_1 = _e191;
            let _e192 = pk_1;
            if (_e192 <= 0f) {
                continue;
            }
            let _e194 = x_2;
            let _e195 = before;
            let _e196 = pk_1;
            if (_e194 < (_e195 + _e196)) {
                let _e199 = k_2;
                chosen = _e199;
                let _e200 = pk_1;
                p_2 = _e200;
                break;
            }
            let _e201 = k_2;
            last = _e201;
            let _e202 = before;
            lastBefore = _e202;
            let _e203 = pk_1;
            let _e204 = before;
            before = (_e204 + _e203);
            continue;
        } else {
            break;
        }
        continuing {
            let _e206 = k_2;
            k_2 = (_e206 + 1i);
        }
    }
    let _e208 = chosen;
    if (_e208 < 0i) {
        let _e210 = last;
        chosen = max(_e210, 0i);
        let _e212 = chosen;
        let _e215 = (*c_7).choice[_e212];
        p_2 = _e215;
        let _e216 = lastBefore;
        before = _e216;
    }
    let _e217 = p_2;
    if (_e217 <= 0f) {
        let _e219 = s_9;
        return _e219;
    }
    let _e220 = x_2;
    let _e221 = before;
    let _e223 = p_2;
    uz = clamp(((_e220 - _e221) / _e223), 0f, 0.99999994f);
    let _e226 = chosen;
    let _e229 = (*c_7).lobes[_e226];
    l_11 = _e229;
    let _e231 = l_11.N;
    param_109 = _e231;
    let _e233 = l_11.T;
    param_110 = _e233;
    let _e234 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_109), (&param_110));
    frame_3 = _e234;
    let _e235 = frame_3;
    param_111 = _e235;
    let _e236 = (*wo_10);
    param_112 = _e236;
    let _e237 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_111), (&param_112));
    o_3 = _e237;
    let _e238 = chosen;
    let _e241 = (*c_7).msPick[_e238];
    q = _e241;
    let _e242 = uz;
    let _e243 = q;
    shaped_1 = (_e242 < _e243);
    reflected = true;
    let _e245 = shaped_1;
    if _e245 {
        let _e246 = uz;
        let _e247 = q;
        v_5 = (_e246 / _e247);
        let _e249 = chosen;
        let _e252 = (*c_7).msSplit[_e249];
        split = _e252;
        let _e253 = v_5;
        let _e254 = split;
        reflected = (_e253 < _e254);
        let _e256 = reflected;
        if _e256 {
            let _e257 = v_5;
            let _e258 = split;
            local_26 = (_e257 / max(_e258, 0.000001f));
        } else {
            let _e261 = v_5;
            let _e262 = split;
            let _e264 = split;
            local_26 = ((_e261 - _e262) / max((1f - _e264), 0.000001f));
        }
        let _e268 = local_26;
        uz = _e268;
    } else {
        let _e269 = uz;
        let _e270 = q;
        let _e272 = q;
        uz = ((_e269 - _e270) / (1f - _e272));
    }
    let _e275 = shaped_1;
    if _e275 {
        let _e276 = reflected;
        let _e278 = l_11;
        param_113 = _e278;
        param_114 = !(_e276);
        let _e279 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_113), (&param_114));
        local_27 = _e279;
    } else {
        let _e280 = l_11;
        local_27 = _e280;
    }
    let _e281 = local_27;
    m_7 = _e281;
    let _e282 = (*u_5);
    let _e283 = _e282.xy;
    let _e284 = uz;
    let _e289 = m_7;
    param_115 = _e289;
    let _e290 = o_3;
    param_116 = _e290;
    param_117 = vec3<f32>(_e283.x, _e283.y, min(_e284, 0.99999994f));
    let _e291 = mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_115), (&param_116), (&param_117));
    ls = _e291;
    let _e293 = ls.valid;
    if !(_e293) {
        let _e295 = s_9;
        return _e295;
    }
    let _e296 = frame_3;
    param_118 = _e296;
    let _e298 = ls.wi;
    param_119 = _e298;
    let _e299 = mxc_to_world_u0028_mf33_u003b_vf3_u003b((&param_118), (&param_119));
    s_9.wi = _e299;
    let _e302 = ls.delta;
    if _e302 {
        s_9.delta = true;
        let _e305 = ls.pdf;
        let _e306 = p_2;
        let _e308 = total;
        s_9.pdf = ((_e305 * _e306) / _e308);
        let _e312 = l_11.weight;
        let _e313 = chosen;
        let _e316 = (*c_7).ms[_e313];
        let _e320 = ls.wi[2u];
        let _e322 = l_11;
        param_120 = _e322;
        param_121 = abs(_e320);
        let _e323 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_120), (&param_121));
        let _e326 = ls.value;
        let _e329 = s_9.pdf;
        s_9.weight = ((((_e312 * _e316) * _e323) * _e326) / vec3(_e329));
        let _e334 = s_9.pdf;
        s_9.valid = (_e334 > 0f);
        let _e337 = s_9;
        return _e337;
    }
    s_9.evaluate = true;
    s_9.valid = true;
    let _e340 = s_9;
    return _e340;
}

fn mxc_radical_inverse_u0028_u1_u003b_u1_u003b(i_5: ptr<function, u32>, base: ptr<function, u32>) -> f32 {
    var inv: f32;
    var f_5: f32;
    var r_3: f32;

    let _e130 = (*base);
    if (_e130 == 2u) {
        let _e132 = (*i_5);
        return (f32((reverseBits(_e132) >> bitcast<u32>(8i))) * 0.000000059604645f);
    }
    let _e138 = (*base);
    inv = (1f / f32(_e138));
    let _e141 = inv;
    f_5 = _e141;
    r_3 = 0f;
    loop {
        let _e142 = (*i_5);
        if (_e142 > 0u) {
            let _e144 = f_5;
            let _e145 = (*i_5);
            let _e146 = (*base);
            let _e150 = r_3;
            r_3 = (_e150 + (_e144 * f32((_e145 % _e146))));
            let _e152 = inv;
            let _e153 = f_5;
            f_5 = (_e153 * _e152);
            continue;
        } else {
            break;
        }
        continuing {
            let _e155 = (*base);
            let _e156 = (*i_5);
            (*i_5) = (_e156 / _e155);
        }
    }
    let _e158 = r_3;
    return min(_e158, 0.99999994f);
}

fn mxc_pcg_u0028_u1_u003b(v_6: ptr<function, u32>) -> u32 {
    var state: u32;
    var word: u32;

    let _e128 = (*v_6);
    state = ((_e128 * 747796405u) + 2891336453u);
    let _e131 = state;
    let _e132 = state;
    let _e138 = state;
    word = (((_e131 >> bitcast<u32>(((_e132 >> bitcast<u32>(28u)) + 4u))) ^ _e138) * 277803737u);
    let _e141 = word;
    let _e144 = word;
    return ((_e141 >> bitcast<u32>(22u)) ^ _e144);
}

fn mxc_uniform_u0028_u1_u003b(seed: ptr<function, u32>) -> f32 {
    var param_122: u32;

    let _e127 = (*seed);
    param_122 = _e127;
    let _e128 = mxc_pcg_u0028_u1_u003b((&param_122));
    (*seed) = _e128;
    let _e129 = (*seed);
    return (f32((_e129 >> bitcast<u32>(8i))) * 0.000000059604645f);
}

fn mxc_light_kinds_u0028_() -> i32 {
    return 7i;
}

fn mxc_light_count_u0028_() -> i32 {
    var local_28: i32;

    if false {
        local_28 = MXC_LIGHT_COUNT;
    } else {
        let _e128 = mxc_view.counts[0u];
        local_28 = _e128;
    }
    let _e129 = local_28;
    return min(_e129, 8i);
}

fn mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b(mu_3: ptr<function, f32>, x_3: ptr<function, f32>, firstRow: ptr<function, f32>) -> vec4<f32> {
    var t_3: vec2<f32>;

    let _e129 = (*mu_3);
    let _e132 = (*x_3);
    t_3 = ((vec2<f32>(sqrt(clamp(_e129, 0f, 1f)), clamp(_e132, 0f, 1f)) * 31f) + vec2(0.5f));
    let _e139 = t_3[0u];
    let _e141 = (*firstRow);
    let _e143 = t_3[1u];
    let _e147 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, vec2<f32>((_e139 / 32f), ((_e141 + _e143) / 2070f)), 0f);
    return _e147;
}

fn mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b(mu_4: ptr<function, f32>, alpha_8: ptr<function, f32>, e: ptr<function, f32>) -> vec4<f32> {
    var s_10: f32;
    var s0_: f32;
    var x_4: f32;
    var a_5: vec4<f32>;
    var param_123: f32;
    var param_124: f32;
    var param_125: f32;
    var b_2: vec4<f32>;
    var param_126: f32;
    var param_127: f32;
    var param_128: f32;

    let _e139 = (*e);
    s_10 = (sqrt(clamp((0.5f * (_e139 - 1f)), 0f, 1f)) * 31f);
    let _e145 = s_10;
    s0_ = min(floor(_e145), 30f);
    let _e148 = (*alpha_8);
    x_4 = sqrt(max(_e148, 0f));
    let _e151 = s0_;
    let _e154 = (*mu_4);
    param_123 = _e154;
    let _e155 = x_4;
    param_124 = _e155;
    param_125 = (32f * (1f + _e151));
    let _e156 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_123), (&param_124), (&param_125));
    a_5 = _e156;
    let _e157 = s0_;
    let _e160 = (*mu_4);
    param_126 = _e160;
    let _e161 = x_4;
    param_127 = _e161;
    param_128 = (32f * (2f + _e157));
    let _e162 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_126), (&param_127), (&param_128));
    b_2 = _e162;
    let _e163 = a_5;
    let _e164 = b_2;
    let _e165 = s_10;
    let _e166 = s0_;
    return mix(_e163, _e164, vec4((_e165 - _e166)));
}

fn mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b(mu_5: ptr<function, f32>, alpha_9: ptr<function, f32>, eta_1: ptr<function, f32>) -> f32 {
    var param_129: f32;
    var param_130: f32;
    var param_131: f32;
    var param_132: f32;
    var param_133: f32;
    var param_134: f32;

    let _e134 = (*eta_1);
    if (_e134 >= 1f) {
        let _e136 = (*mu_5);
        param_129 = _e136;
        let _e137 = (*alpha_9);
        param_130 = _e137;
        let _e138 = (*eta_1);
        param_131 = _e138;
        let _e139 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_129), (&param_130), (&param_131));
        return _e139.y;
    }
    let _e141 = (*eta_1);
    let _e144 = (*mu_5);
    param_132 = _e144;
    let _e145 = (*alpha_9);
    param_133 = _e145;
    param_134 = (1f / max(_e141, 0.001f));
    let _e146 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_132), (&param_133), (&param_134));
    return _e146.z;
}

fn mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b(mu_6: ptr<function, f32>, alpha_10: ptr<function, f32>, eta_2: ptr<function, f32>) -> f32 {
    var e_1: f32;
    var local_29: f32;
    var param_135: f32;
    var param_136: f32;
    var param_137: f32;

    let _e133 = (*eta_2);
    if (_e133 >= 1f) {
        let _e135 = (*eta_2);
        local_29 = _e135;
    } else {
        let _e136 = (*eta_2);
        local_29 = (1f / max(_e136, 0.001f));
    }
    let _e139 = local_29;
    e_1 = _e139;
    let _e140 = (*mu_6);
    param_135 = _e140;
    let _e141 = (*alpha_10);
    param_136 = _e141;
    let _e142 = e_1;
    param_137 = _e142;
    let _e143 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_135), (&param_136), (&param_137));
    return _e143.x;
}

fn mxc_table_u0028_f1_u003b_f1_u003b(mu_7: ptr<function, f32>, x_5: ptr<function, f32>) -> vec4<f32> {
    var param_138: f32;
    var param_139: f32;
    var param_140: f32;

    let _e130 = (*mu_7);
    param_138 = _e130;
    let _e131 = (*x_5);
    param_139 = _e131;
    param_140 = 0f;
    let _e132 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_138), (&param_139), (&param_140));
    return _e132;
}

fn mxc_split_sum_u0028_f1_u003b_f1_u003b(mu_8: ptr<function, f32>, alpha_11: ptr<function, f32>) -> vec2<f32> {
    var param_141: f32;
    var param_142: f32;

    let _e129 = (*alpha_11);
    let _e132 = (*mu_8);
    param_141 = _e132;
    param_142 = sqrt(max(_e129, 0f));
    let _e133 = mxc_table_u0028_f1_u003b_f1_u003b((&param_141), (&param_142));
    return _e133.xy;
}

fn mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_12: ptr<function, MxcLobe>, wo_11: ptr<function, vec3<f32>>, ms: ptr<function, vec3<f32>>) -> vec3<f32> {
    var mu_9: f32;
    var alpha_12: f32;
    var param_143: vec2<f32>;
    var e_2: vec3<f32>;
    var param_144: MxcLobe;
    var param_145: f32;
    var param_146: f32;
    var param_147: f32;
    var param_148: f32;
    var ab: vec2<f32>;
    var param_149: f32;
    var param_150: f32;
    var f0_: vec3<f32>;
    var param_151: MxcLobe;
    var param_152: f32;
    var param_153: bool;
    var f90_: vec3<f32>;
    var param_154: MxcLobe;
    var param_155: f32;
    var param_156: bool;
    var tint_1: vec3<f32>;
    var local_30: vec3<f32>;
    var param_157: vec2<f32>;
    var param_158: MxcLobe;
    var param_159: f32;
    var param_160: bool;
    var phi_2441_: bool;
    var phi_2448_: bool;
    var phi_2466_: bool;

    let _e155 = (*wo_11)[2u];
    mu_9 = clamp(_e155, 0f, 1f);
    let _e158 = (*l_12).kind;
    let _e159 = (_e158 == 1i);
    phi_2441_ = _e159;
    if !(_e159) {
        let _e162 = (*l_12).kind;
        phi_2441_ = (_e162 == 2i);
    }
    let _e165 = phi_2441_;
    phi_2448_ = _e165;
    if !(_e165) {
        let _e168 = (*l_12).kind;
        phi_2448_ = (_e168 == 3i);
    }
    let _e171 = phi_2448_;
    if _e171 {
        let _e174 = (*l_12).alpha[0u];
        let _e177 = (*l_12).alpha[1u];
        alpha_12 = sqrt((_e174 * _e177));
        let _e181 = (*l_12).kind;
        let _e182 = (_e181 == 1i);
        phi_2466_ = _e182;
        if _e182 {
            let _e184 = (*l_12).alpha;
            param_143 = _e184;
            let _e185 = mxc_is_delta_u0028_vf2_u003b((&param_143));
            phi_2466_ = !(_e185);
        }
        let _e188 = phi_2466_;
        if _e188 {
            let _e189 = (*l_12);
            param_144 = _e189;
            let _e190 = mu_9;
            param_145 = _e190;
            let _e191 = mxc_lobe_cosine_below_coat_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_144), (&param_145));
            param_146 = _e191;
            let _e192 = alpha_12;
            param_147 = _e192;
            let _e194 = (*l_12).eta;
            param_148 = _e194;
            let _e195 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_146), (&param_147), (&param_148));
            e_2 = vec3(_e195);
            let _e197 = e_2;
            let _e199 = (*l_12).c0_;
            let _e201 = (*ms);
            return clamp(((_e197 * _e199) * _e201), vec3(0f), vec3(1f));
        }
        let _e206 = mu_9;
        param_149 = _e206;
        let _e207 = alpha_12;
        param_150 = _e207;
        let _e208 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_149), (&param_150));
        ab = _e208;
        let _e209 = (*l_12);
        param_151 = _e209;
        param_152 = 1f;
        param_153 = true;
        let _e210 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_151), (&param_152), (&param_153));
        f0_ = _e210;
        let _e211 = (*l_12);
        param_154 = _e211;
        param_155 = 0f;
        param_156 = true;
        let _e212 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_154), (&param_155), (&param_156));
        f90_ = _e212;
        let _e214 = (*l_12).kind;
        if (_e214 == 1i) {
            let _e217 = (*l_12).c0_;
            local_30 = _e217;
        } else {
            local_30 = vec3<f32>(1f, 1f, 1f);
        }
        let _e218 = local_30;
        tint_1 = _e218;
        let _e220 = (*l_12).alpha;
        param_157 = _e220;
        let _e221 = mxc_is_delta_u0028_vf2_u003b((&param_157));
        if _e221 {
            let _e222 = (*l_12);
            param_158 = _e222;
            let _e223 = mu_9;
            param_159 = _e223;
            param_160 = true;
            let _e224 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_158), (&param_159), (&param_160));
            let _e225 = tint_1;
            return (_e224 * _e225);
        }
        let _e227 = f0_;
        let _e229 = ab[0u];
        let _e231 = f90_;
        let _e233 = ab[1u];
        let _e236 = tint_1;
        let _e238 = (*ms);
        return clamp(((((_e227 * _e229) + (_e231 * _e233)) * _e236) * _e238), vec3(0f), vec3(1f));
    }
    let _e244 = (*l_12).kind;
    if (_e244 == 8i) {
        let _e247 = (*l_12).c0_;
        return _e247;
    }
    let _e249 = (*l_12).c0_;
    return _e249;
}

fn mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_13: ptr<function, MxcLobe>, wo_12: ptr<function, vec3<f32>>) -> bool {
    var phi_2065_: bool;

    let _e128 = (*wo_12)[2u];
    let _e129 = (_e128 <= 0f);
    phi_2065_ = _e129;
    if !(_e129) {
        let _e132 = (*l_13).eta;
        phi_2065_ = (_e132 < 1f);
    }
    let _e135 = phi_2065_;
    if _e135 {
        return false;
    }
    return true;
}

fn mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_14: ptr<function, MxcLobe>) -> bool {
    let _e127 = (*l_14).eta;
    return (abs((_e127 - 1f)) < 0.0001f);
}

fn mxc_lobe_ms_shaped_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_15: ptr<function, MxcLobe>, wo_13: ptr<function, vec3<f32>>) -> bool {
    var param_161: vec2<f32>;
    var param_162: MxcLobe;
    var param_163: MxcLobe;
    var param_164: vec3<f32>;
    var phi_2318_: bool;
    var phi_2344_: bool;
    var phi_2351_: bool;
    var phi_2357_: bool;
    var phi_2363_: bool;

    let _e132 = (*wo_13)[2u];
    let _e133 = (_e132 <= 0f);
    phi_2318_ = _e133;
    if !(_e133) {
        let _e136 = (*l_15).alpha;
        param_161 = _e136;
        let _e137 = mxc_is_delta_u0028_vf2_u003b((&param_161));
        phi_2318_ = _e137;
    }
    let _e139 = phi_2318_;
    if _e139 {
        return false;
    }
    let _e141 = (*l_15).kind;
    if (_e141 == 2i) {
        return true;
    }
    let _e144 = (*l_15).kind;
    if (_e144 == 3i) {
        let _e147 = (*l_15).mode;
        return ((_e147 & 1i) != 0i);
    }
    let _e151 = (*l_15).kind;
    let _e152 = (_e151 == 1i);
    phi_2344_ = _e152;
    if _e152 {
        let _e154 = (*l_15).mode;
        phi_2344_ = ((_e154 & 1i) != 0i);
    }
    let _e158 = phi_2344_;
    phi_2351_ = _e158;
    if _e158 {
        let _e160 = (*l_15).mode;
        phi_2351_ = ((_e160 & 4i) == 0i);
    }
    let _e164 = phi_2351_;
    phi_2357_ = _e164;
    if _e164 {
        let _e165 = (*l_15);
        param_162 = _e165;
        let _e166 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_162));
        phi_2357_ = !(_e166);
    }
    let _e169 = phi_2357_;
    phi_2363_ = _e169;
    if _e169 {
        let _e170 = (*l_15);
        param_163 = _e170;
        let _e171 = (*wo_13);
        param_164 = _e171;
        let _e172 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_163), (&param_164));
        phi_2363_ = _e172;
    }
    let _e174 = phi_2363_;
    return _e174;
}

fn mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_16: ptr<function, MxcLobe>, woLocal: ptr<function, vec3<f32>>, ms_1: ptr<function, vec3<f32>>) -> f32 {
    var param_165: MxcLobe;
    var param_166: vec3<f32>;
    var param_167: vec3<f32>;
    var param_168: vec3<f32>;

    let _e133 = (*l_16).weight;
    if all((_e133 == vec3<f32>(0f, 0f, 0f))) {
        return 0f;
    }
    let _e137 = (*l_16).weight;
    let _e138 = (*l_16);
    param_165 = _e138;
    let _e139 = (*woLocal);
    param_166 = _e139;
    let _e140 = (*ms_1);
    param_167 = _e140;
    let _e141 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_165), (&param_166), (&param_167));
    param_168 = (_e137 * _e141);
    let _e143 = mxc_luminance_u0028_vf3_u003b((&param_168));
    return (max(_e143, 0f) + 0.0001f);
}

fn mxc_walk_texel_u0028_f1_u003b_f1_u003b(column: ptr<function, f32>, row: ptr<function, f32>) -> f32 {
    var t_4: vec2<f32>;

    let _e128 = (*column);
    let _e130 = (*row);
    t_4 = (vec2<f32>((_e128 + 0.5f), (_e130 + 0.5f)) / vec2<f32>(32f, 2070f));
    let _e134 = t_4;
    let _e135 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, _e134, 0f);
    return _e135.x;
}

fn mxc_walk_eta_index_u0028_f1_u003b(eta_3: ptr<function, f32>) -> f32 {
    var e_3: f32;

    let _e127 = (*eta_3);
    e_3 = max(_e127, 1f);
    let _e129 = e_3;
    let _e132 = e_3;
    return (clamp(((2f * (_e129 - 1f)) / (_e132 + 1f)), 0f, 1f) * 12f);
}

fn mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b(mu_10: ptr<function, f32>, alpha_13: ptr<function, f32>, eta_4: ptr<function, f32>) -> f32 {
    var fe: f32;
    var param_169: f32;
    var e0_: f32;
    var column_1: f32;
    var row_1: f32;
    var a_6: f32;
    var param_170: f32;
    var param_171: f32;
    var b_3: f32;
    var param_172: f32;
    var param_173: f32;

    let _e139 = (*eta_4);
    param_169 = _e139;
    let _e140 = mxc_walk_eta_index_u0028_f1_u003b((&param_169));
    fe = _e140;
    let _e141 = fe;
    e0_ = min(floor(_e141), 11f);
    let _e144 = (*mu_10);
    column_1 = (sqrt(clamp(_e144, 0f, 1f)) * 31f);
    let _e148 = (*alpha_13);
    row_1 = (1654f + (sqrt(clamp(_e148, 0f, 1f)) * 31f));
    let _e153 = row_1;
    let _e154 = e0_;
    let _e157 = column_1;
    param_170 = _e157;
    param_171 = (_e153 + (_e154 * 32f));
    let _e158 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_170), (&param_171));
    a_6 = _e158;
    let _e159 = row_1;
    let _e160 = e0_;
    let _e164 = column_1;
    param_172 = _e164;
    param_173 = (_e159 + ((_e160 + 1f) * 32f));
    let _e165 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_172), (&param_173));
    b_3 = _e165;
    let _e166 = a_6;
    let _e167 = b_3;
    let _e168 = fe;
    let _e169 = e0_;
    return mix(_e166, _e167, (_e168 - _e169));
}

fn mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_17: ptr<function, MxcLobe>, wo_14: ptr<function, vec3<f32>>, ms_2: ptr<function, vec3<f32>>) -> f32 {
    var param_174: vec2<f32>;
    var param_175: MxcLobe;
    var param_176: MxcLobe;
    var param_177: vec3<f32>;
    var alpha_14: f32;
    var rss: f32;
    var param_178: f32;
    var param_179: f32;
    var param_180: f32;
    var tss: f32;
    var param_181: f32;
    var param_182: f32;
    var param_183: f32;
    var param_184: f32;
    var param_185: f32;
    var param_186: f32;
    var phi_2098_: bool;
    var phi_2104_: bool;
    var phi_2112_: bool;
    var phi_2120_: bool;

    let _e145 = (*l_17).kind;
    let _e146 = (_e145 != 1i);
    phi_2098_ = _e146;
    if !(_e146) {
        let _e149 = (*l_17).alpha;
        param_174 = _e149;
        let _e150 = mxc_is_delta_u0028_vf2_u003b((&param_174));
        phi_2098_ = _e150;
    }
    let _e152 = phi_2098_;
    phi_2104_ = _e152;
    if !(_e152) {
        let _e154 = (*l_17);
        param_175 = _e154;
        let _e155 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_175));
        phi_2104_ = _e155;
    }
    let _e157 = phi_2104_;
    phi_2112_ = _e157;
    if !(_e157) {
        let _e160 = (*l_17).mode;
        phi_2112_ = ((_e160 & 4i) != 0i);
    }
    let _e164 = phi_2112_;
    phi_2120_ = _e164;
    if !(_e164) {
        let _e166 = (*l_17);
        param_176 = _e166;
        let _e167 = (*wo_14);
        param_177 = _e167;
        let _e168 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_176), (&param_177));
        phi_2120_ = !(_e168);
    }
    let _e171 = phi_2120_;
    if _e171 {
        let _e173 = (*ms_2)[0u];
        return _e173;
    }
    let _e176 = (*l_17).alpha[0u];
    let _e179 = (*l_17).alpha[1u];
    alpha_14 = sqrt((_e176 * _e179));
    let _e183 = (*wo_14)[2u];
    param_178 = _e183;
    let _e184 = alpha_14;
    param_179 = _e184;
    let _e186 = (*l_17).eta;
    param_180 = _e186;
    let _e187 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_178), (&param_179), (&param_180));
    rss = _e187;
    let _e189 = (*wo_14)[2u];
    param_181 = _e189;
    let _e190 = alpha_14;
    param_182 = _e190;
    let _e192 = (*l_17).eta;
    param_183 = _e192;
    let _e193 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_181), (&param_182), (&param_183));
    let _e194 = rss;
    tss = (_e193 - _e194);
    let _e197 = (*wo_14)[2u];
    param_184 = _e197;
    let _e198 = alpha_14;
    param_185 = _e198;
    let _e200 = (*l_17).eta;
    param_186 = _e200;
    let _e201 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_184), (&param_185), (&param_186));
    let _e203 = tss;
    return clamp(((1f - _e201) / max(_e203, 0.05f)), 1f, 20f);
}

fn mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_18: ptr<function, MxcLobe>, wo_15: ptr<function, vec3<f32>>) -> vec3<f32> {
    var microfacet: bool;
    var param_187: vec2<f32>;
    var alpha_15: f32;
    var param_188: MxcLobe;
    var param_189: MxcLobe;
    var param_190: vec3<f32>;
    var rss_1: f32;
    var param_191: f32;
    var param_192: f32;
    var param_193: f32;
    var param_194: f32;
    var param_195: f32;
    var param_196: f32;
    var e_4: f32;
    var param_197: MxcLobe;
    var param_198: bool;
    var param_199: f32;
    var param_200: f32;
    var param_201: f32;
    var k_3: vec3<f32>;
    var ab_1: vec2<f32>;
    var param_202: f32;
    var param_203: f32;
    var e_5: f32;
    var param_204: MxcLobe;
    var param_205: f32;
    var param_206: bool;
    var phi_2196_: bool;
    var phi_2203_: bool;
    var phi_2212_: bool;
    var phi_2228_: bool;
    var phi_2240_: bool;

    let _e155 = (*l_18).kind;
    let _e156 = (_e155 == 1i);
    phi_2196_ = _e156;
    if !(_e156) {
        let _e159 = (*l_18).kind;
        phi_2196_ = (_e159 == 2i);
    }
    let _e162 = phi_2196_;
    phi_2203_ = _e162;
    if !(_e162) {
        let _e165 = (*l_18).kind;
        phi_2203_ = (_e165 == 3i);
    }
    let _e168 = phi_2203_;
    microfacet = _e168;
    let _e169 = microfacet;
    let _e170 = !(_e169);
    phi_2212_ = _e170;
    if !(_e170) {
        let _e173 = (*l_18).alpha;
        param_187 = _e173;
        let _e174 = mxc_is_delta_u0028_vf2_u003b((&param_187));
        phi_2212_ = _e174;
    }
    let _e176 = phi_2212_;
    if _e176 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e179 = (*l_18).alpha[0u];
    let _e182 = (*l_18).alpha[1u];
    alpha_15 = sqrt((_e179 * _e182));
    let _e186 = (*l_18).kind;
    let _e187 = (_e186 == 1i);
    phi_2228_ = _e187;
    if _e187 {
        let _e188 = (*l_18);
        param_188 = _e188;
        let _e189 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_188));
        phi_2228_ = _e189;
    }
    let _e191 = phi_2228_;
    if _e191 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e193 = (*l_18).kind;
    let _e194 = (_e193 == 1i);
    phi_2240_ = _e194;
    if _e194 {
        let _e196 = (*l_18).mode;
        phi_2240_ = ((_e196 & 4i) == 0i);
    }
    let _e200 = phi_2240_;
    if _e200 {
        let _e201 = (*l_18);
        param_189 = _e201;
        let _e202 = (*wo_15);
        param_190 = _e202;
        let _e203 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_189), (&param_190));
        if _e203 {
            let _e205 = (*wo_15)[2u];
            param_191 = _e205;
            let _e206 = alpha_15;
            param_192 = _e206;
            let _e208 = (*l_18).eta;
            param_193 = _e208;
            let _e209 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_191), (&param_192), (&param_193));
            rss_1 = _e209;
            let _e211 = (*wo_15)[2u];
            param_194 = _e211;
            let _e212 = alpha_15;
            param_195 = _e212;
            let _e214 = (*l_18).eta;
            param_196 = _e214;
            let _e215 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_194), (&param_195), (&param_196));
            let _e216 = rss_1;
            return vec3(clamp((_e215 / max(_e216, 0.0001f)), 1f, 20f));
        }
        let _e222 = (*wo_15)[2u];
        let _e225 = (*wo_15)[2u];
        let _e227 = (*l_18);
        param_197 = _e227;
        param_198 = (_e225 >= 0f);
        let _e228 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_197), (&param_198));
        param_199 = abs(_e222);
        let _e229 = alpha_15;
        param_200 = _e229;
        param_201 = _e228;
        let _e230 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_199), (&param_200), (&param_201));
        e_4 = _e230;
        let _e231 = e_4;
        k_3 = vec3((1f / max(_e231, 0.05f)));
        let _e235 = k_3;
        return _e235;
    }
    let _e237 = (*wo_15)[2u];
    param_202 = max(_e237, 0f);
    let _e239 = alpha_15;
    param_203 = _e239;
    let _e240 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_202), (&param_203));
    ab_1 = _e240;
    let _e242 = ab_1[0u];
    let _e244 = ab_1[1u];
    e_5 = (_e242 + _e244);
    let _e246 = (*l_18);
    param_204 = _e246;
    param_205 = 1f;
    param_206 = true;
    let _e247 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_204), (&param_205), (&param_206));
    let _e248 = e_5;
    let _e251 = e_5;
    return (vec3(1f) + ((_e247 * (1f - _e248)) / vec3(max(_e251, 0.05f))));
}

fn mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b(c_8: ptr<function, MxcClosure>, wo_16: ptr<function, vec3<f32>>) {
    var k_4: i32;
    var l_19: MxcLobe;
    var o_4: vec3<f32>;
    var param_207: vec3<f32>;
    var param_208: vec3<f32>;
    var param_209: mat3x3<f32>;
    var param_210: vec3<f32>;
    var ms_3: vec3<f32>;
    var param_211: MxcLobe;
    var param_212: vec3<f32>;
    var param_213: MxcLobe;
    var param_214: vec3<f32>;
    var param_215: vec3<f32>;
    var param_216: MxcLobe;
    var param_217: vec3<f32>;
    var param_218: vec3<f32>;
    var param_219: MxcLobe;
    var param_220: vec3<f32>;
    var alpha_16: f32;
    var reflected_1: vec3<f32>;
    var param_221: MxcLobe;
    var param_222: vec3<f32>;
    var param_223: vec3<f32>;
    var addedR: vec3<f32>;
    var param_224: MxcLobe;
    var param_225: vec3<f32>;
    var param_226: vec3<f32>;
    var transmitted_1: vec3<f32>;
    var addedT: vec3<f32>;
    var param_227: MxcLobe;
    var rss_2: f32;
    var param_228: f32;
    var param_229: f32;
    var param_230: f32;
    var param_231: f32;
    var param_232: f32;
    var param_233: f32;
    var mr: MxcLobe;
    var param_234: MxcLobe;
    var param_235: bool;
    var broadR: vec3<f32>;
    var param_236: MxcLobe;
    var param_237: vec3<f32>;
    var param_238: vec3<f32>;
    var broadT: f32;
    var param_239: MxcLobe;
    var mt: MxcLobe;
    var param_240: MxcLobe;
    var param_241: bool;
    var at: f32;
    var param_242: f32;
    var param_243: f32;
    var param_244: f32;
    var param_245: f32;
    var param_246: f32;
    var param_247: f32;
    var total_1: f32;
    var param_248: vec3<f32>;
    var added: f32;
    var param_249: vec3<f32>;
    var local_31: f32;
    var param_250: vec3<f32>;
    var phi_3224_: bool;
    var phi_3264_: bool;

    (*c_8).choiceTotal = 0f;
    k_4 = 0i;
    loop {
        let _e190 = k_4;
        let _e192 = (*c_8).count;
        if (_e190 < _e192) {
            let _e194 = k_4;
            let _e197 = (*c_8).lobes[_e194];
            l_19 = _e197;
            let _e198 = k_4;
            (*c_8).ms[_e198] = vec3<f32>(1f, 1f, 1f);
            let _e201 = k_4;
            (*c_8).msT[_e201] = 1f;
            let _e204 = k_4;
            (*c_8).msLobe[_e204] = vec3<f32>(0f, 0f, 0f);
            let _e207 = k_4;
            (*c_8).msLobeT[_e207] = vec3<f32>(0f, 0f, 0f);
            let _e210 = k_4;
            (*c_8).msPick[_e210] = 0f;
            let _e213 = k_4;
            (*c_8).msSplit[_e213] = 1f;
            let _e216 = k_4;
            (*c_8).choice[_e216] = 0f;
            let _e220 = l_19.weight;
            if all((_e220 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e224 = l_19.N;
            param_207 = _e224;
            let _e226 = l_19.T;
            param_208 = _e226;
            let _e227 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_207), (&param_208));
            param_209 = _e227;
            let _e228 = (*wo_16);
            param_210 = _e228;
            let _e229 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_209), (&param_210));
            o_4 = _e229;
            let _e230 = l_19;
            param_211 = _e230;
            let _e231 = o_4;
            param_212 = _e231;
            let _e232 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_211), (&param_212));
            ms_3 = _e232;
            let _e233 = k_4;
            let _e234 = l_19;
            param_213 = _e234;
            let _e235 = o_4;
            param_214 = _e235;
            let _e236 = ms_3;
            param_215 = _e236;
            let _e237 = mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_213), (&param_214), (&param_215));
            (*c_8).msT[_e233] = _e237;
            let _e240 = k_4;
            let _e241 = l_19;
            param_216 = _e241;
            let _e242 = o_4;
            param_217 = _e242;
            let _e243 = ms_3;
            param_218 = _e243;
            let _e244 = mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_216), (&param_217), (&param_218));
            (*c_8).choice[_e240] = _e244;
            let _e247 = k_4;
            let _e250 = (*c_8).choice[_e247];
            let _e252 = (*c_8).choiceTotal;
            (*c_8).choiceTotal = (_e252 + _e250);
            let _e255 = l_19;
            param_219 = _e255;
            let _e256 = o_4;
            param_220 = _e256;
            let _e257 = mxc_lobe_ms_shaped_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_219), (&param_220));
            if _e257 {
                let _e260 = l_19.alpha[0u];
                let _e263 = l_19.alpha[1u];
                alpha_16 = sqrt((_e260 * _e263));
                let _e266 = l_19;
                param_221 = _e266;
                let _e267 = o_4;
                param_222 = _e267;
                param_223 = vec3<f32>(1f, 1f, 1f);
                let _e268 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_221), (&param_222), (&param_223));
                reflected_1 = _e268;
                let _e269 = l_19;
                param_224 = _e269;
                let _e270 = o_4;
                param_225 = _e270;
                let _e271 = ms_3;
                param_226 = _e271;
                let _e272 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_224), (&param_225), (&param_226));
                let _e273 = reflected_1;
                addedR = max((_e272 - _e273), vec3<f32>(0f, 0f, 0f));
                transmitted_1 = vec3<f32>(0f, 0f, 0f);
                addedT = vec3<f32>(0f, 0f, 0f);
                let _e277 = l_19.kind;
                let _e278 = (_e277 == 1i);
                phi_3224_ = _e278;
                if _e278 {
                    let _e279 = l_19;
                    param_227 = _e279;
                    let _e280 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_227));
                    phi_3224_ = _e280;
                }
                let _e282 = phi_3224_;
                if _e282 {
                    let _e284 = o_4[2u];
                    param_228 = _e284;
                    let _e285 = alpha_16;
                    param_229 = _e285;
                    let _e287 = l_19.eta;
                    param_230 = _e287;
                    let _e288 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_228), (&param_229), (&param_230));
                    rss_2 = _e288;
                    let _e290 = o_4[2u];
                    param_231 = _e290;
                    let _e291 = alpha_16;
                    param_232 = _e291;
                    let _e293 = l_19.eta;
                    param_233 = _e293;
                    let _e294 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_231), (&param_232), (&param_233));
                    let _e295 = rss_2;
                    let _e299 = l_19.c1_;
                    transmitted_1 = (_e299 * max((_e294 - _e295), 0f));
                    let _e301 = k_4;
                    let _e304 = (*c_8).msT[_e301];
                    let _e307 = transmitted_1;
                    addedT = (_e307 * max((_e304 - 1f), 0f));
                }
                let _e309 = l_19;
                param_234 = _e309;
                param_235 = false;
                let _e310 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_234), (&param_235));
                mr = _e310;
                let _e311 = mr;
                param_236 = _e311;
                let _e312 = o_4;
                param_237 = _e312;
                param_238 = vec3<f32>(1f, 1f, 1f);
                let _e313 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_236), (&param_237), (&param_238));
                broadR = _e313;
                broadT = 1f;
                let _e315 = l_19.kind;
                let _e316 = (_e315 == 1i);
                phi_3264_ = _e316;
                if _e316 {
                    let _e317 = l_19;
                    param_239 = _e317;
                    let _e318 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_239));
                    phi_3264_ = _e318;
                }
                let _e320 = phi_3264_;
                if _e320 {
                    let _e321 = l_19;
                    param_240 = _e321;
                    param_241 = true;
                    let _e322 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_240), (&param_241));
                    mt = _e322;
                    let _e325 = mt.alpha[0u];
                    let _e328 = mt.alpha[1u];
                    at = sqrt((_e325 * _e328));
                    let _e332 = o_4[2u];
                    param_242 = _e332;
                    let _e333 = at;
                    param_243 = _e333;
                    let _e335 = l_19.eta;
                    param_244 = _e335;
                    let _e336 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_242), (&param_243), (&param_244));
                    let _e338 = o_4[2u];
                    param_245 = _e338;
                    let _e339 = at;
                    param_246 = _e339;
                    let _e341 = l_19.eta;
                    param_247 = _e341;
                    let _e342 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_245), (&param_246), (&param_247));
                    broadT = (_e336 - _e342);
                }
                let _e344 = k_4;
                let _e345 = addedR;
                let _e346 = broadR;
                (*c_8).msLobe[_e344] = (_e345 / max(_e346, vec3<f32>(0.0001f, 0.0001f, 0.0001f)));
                let _e351 = k_4;
                let _e352 = addedT;
                let _e353 = broadT;
                (*c_8).msLobeT[_e351] = (_e352 / vec3(max(_e353, 0.0001f)));
                let _e359 = reflected_1;
                let _e360 = addedR;
                let _e362 = transmitted_1;
                let _e364 = addedT;
                param_248 = (((_e359 + _e360) + _e362) + _e364);
                let _e366 = mxc_luminance_u0028_vf3_u003b((&param_248));
                total_1 = max(_e366, 0.000001f);
                let _e368 = addedR;
                let _e369 = addedT;
                param_249 = (_e368 + _e369);
                let _e371 = mxc_luminance_u0028_vf3_u003b((&param_249));
                added = _e371;
                let _e372 = k_4;
                let _e373 = added;
                let _e374 = total_1;
                (*c_8).msPick[_e372] = (0.999f * min((_e373 / _e374), 1f));
                let _e380 = k_4;
                let _e381 = added;
                if (_e381 > 0f) {
                    let _e383 = addedR;
                    param_250 = _e383;
                    let _e384 = mxc_luminance_u0028_vf3_u003b((&param_250));
                    let _e385 = added;
                    local_31 = (_e384 / _e385);
                } else {
                    local_31 = 1f;
                }
                let _e387 = local_31;
                (*c_8).msSplit[_e380] = _e387;
                let _e390 = k_4;
                (*c_8).msT[_e390] = 1f;
            } else {
                let _e393 = k_4;
                let _e394 = ms_3;
                (*c_8).ms[_e393] = _e394;
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e397 = k_4;
            k_4 = (_e397 + 1i);
        }
    }
    return;
}

fn mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_20: ptr<function, MxcLobe>, wo_17: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_251: MxcLobe;
    var param_252: vec3<f32>;
    var param_253: MxcLobe;
    var param_254: vec3<f32>;
    var param_255: vec3<f32>;

    let _e132 = (*l_20);
    param_251 = _e132;
    let _e133 = (*wo_17);
    param_252 = _e133;
    let _e134 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_251), (&param_252));
    let _e135 = (*l_20);
    param_253 = _e135;
    let _e136 = (*wo_17);
    param_254 = _e136;
    param_255 = _e134;
    let _e137 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_253), (&param_254), (&param_255));
    return _e137;
}

fn mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_21: ptr<function, MxcLobe>, wo_18: ptr<function, vec3<f32>>) -> vec3<f32> {
    var white: MxcLobe;
    var param_256: MxcLobe;
    var param_257: vec3<f32>;
    var param_258: MxcLobe;
    var param_259: vec3<f32>;
    var phi_2570_: bool;

    let _e133 = (*l_21).kind;
    let _e134 = (_e133 == 9i);
    phi_2570_ = _e134;
    if !(_e134) {
        let _e137 = (*l_21).kind;
        phi_2570_ = (_e137 == 10i);
    }
    let _e140 = phi_2570_;
    if _e140 {
        let _e141 = (*l_21);
        white = _e141;
        white.c0_ = vec3<f32>(1f, 1f, 1f);
        let _e143 = white;
        param_256 = _e143;
        let _e144 = (*wo_18);
        param_257 = _e144;
        let _e145 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_256), (&param_257));
        return _e145;
    }
    let _e146 = (*l_21);
    param_258 = _e146;
    let _e147 = (*wo_18);
    param_259 = _e147;
    let _e148 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_258), (&param_259));
    return _e148;
}

fn mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b(g_1: ptr<function, MxcGeometry>, wo_19: ptr<function, vec3<f32>>, c_9: ptr<function, MxcClosure>) {
    var v5_: vec3<f32>;
    var v6_: vec3<f32>;
    var lobe0_: MxcLobe;
    var e1_: vec3<f32>;
    var param_260: vec3<f32>;
    var param_261: vec3<f32>;
    var param_262: mat3x3<f32>;
    var param_263: vec3<f32>;
    var param_264: MxcLobe;
    var param_265: vec3<f32>;
    var w2_: vec3<f32>;
    var lobe3_: MxcLobe;
    var param_266: MxcClosure;
    var param_267: vec3<f32>;

    let _e143 = (*g_1).N;
    v5_ = _e143;
    let _e145 = (*g_1).T;
    v6_ = _e145;
    (*c_9).emission = vec3<f32>(0f, 0f, 0f);
    (*c_9).transparency = vec3<f32>(0f, 0f, 0f);
    lobe0_.kind = 1i;
    lobe0_.mode = 1i;
    let _e150 = v5_;
    lobe0_.N = _e150;
    let _e152 = v6_;
    lobe0_.T = _e152;
    lobe0_.alpha = vec2<f32>(0.09f, 0.09f);
    lobe0_.eta = 1.5f;
    lobe0_.etaAbove = 1f;
    lobe0_.c0_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.p0_ = 0f;
    lobe0_.p1_ = 1f;
    lobe0_.film = vec3<f32>(0f, 0f, 0f);
    lobe0_.tau = vec3<f32>(0f, 0f, 0f);
    lobe0_.tauEta = 1f;
    let _e166 = lobe0_.N;
    param_260 = _e166;
    let _e168 = lobe0_.T;
    param_261 = _e168;
    let _e169 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_260), (&param_261));
    param_262 = _e169;
    let _e170 = (*wo_19);
    param_263 = _e170;
    let _e171 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_262), (&param_263));
    let _e172 = lobe0_;
    param_264 = _e172;
    param_265 = _e171;
    let _e173 = mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_264), (&param_265));
    e1_ = _e173;
    let _e174 = e1_;
    w2_ = (vec3<f32>(1f, 1f, 1f) - _e174);
    lobe3_.kind = 5i;
    lobe3_.mode = 1i;
    let _e178 = v5_;
    lobe3_.N = _e178;
    let _e181 = (*g_1).T;
    lobe3_.T = _e181;
    lobe3_.alpha = vec2<f32>(0f, 0f);
    lobe3_.eta = 1.5f;
    lobe3_.etaAbove = 1f;
    lobe3_.c0_ = vec3<f32>(0.8f, 0.8f, 0.8f);
    lobe3_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.p0_ = 0f;
    lobe3_.p1_ = 1f;
    lobe3_.film = vec3<f32>(0f, 0f, 0f);
    lobe3_.tau = vec3<f32>(0f, 0f, 0f);
    lobe3_.tauEta = 1f;
    lobe0_.weight = vec3<f32>(1f, 1f, 1f);
    let _e195 = lobe0_;
    (*c_9).lobes[0i] = _e195;
    let _e198 = w2_;
    lobe3_.weight = _e198;
    let _e200 = lobe3_;
    (*c_9).lobes[1i] = _e200;
    (*c_9).count = 2i;
    let _e204 = (*c_9);
    param_266 = _e204;
    let _e205 = (*wo_19);
    param_267 = _e205;
    mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b((&param_266), (&param_267));
    let _e206 = param_266;
    (*c_9) = _e206;
    return;
}

fn mxc_closure_seed_u0028_u1_u003b(seed_1: ptr<function, u32>) {
    return;
}

fn mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b(v_7: ptr<function, vec3<f32>>, fallback: ptr<function, vec3<f32>>) -> vec3<f32> {
    var l2_1: f32;
    var local_32: vec3<f32>;

    let _e129 = (*v_7);
    let _e130 = (*v_7);
    l2_1 = dot(_e129, _e130);
    let _e132 = l2_1;
    if (_e132 > 0.00000000000000000001f) {
        let _e134 = (*v_7);
        let _e135 = l2_1;
        local_32 = (_e134 * inverseSqrt(_e135));
    } else {
        let _e138 = (*fallback);
        local_32 = _e138;
    }
    let _e139 = local_32;
    return _e139;
}

fn main_1() {
    var g_2: MxcGeometry;
    var N_1: vec3<f32>;
    var param_268: vec3<f32>;
    var param_269: vec3<f32>;
    var wo_20: vec3<f32>;
    var param_270: vec3<f32>;
    var param_271: vec3<f32>;
    var facing: f32;
    var handedness: f32;
    var frame_4: mat3x3<f32>;
    var param_272: vec3<f32>;
    var param_273: vec3<f32>;
    var param_274: vec3<f32>;
    var param_275: vec3<f32>;
    var objectFrame: mat3x3<f32>;
    var param_276: vec3<f32>;
    var param_277: vec3<f32>;
    var param_278: u32;
    var param_279: u32;
    var param_280: u32;
    var param_281: u32;
    var c_10: MxcClosure;
    var param_282: MxcGeometry;
    var param_283: vec3<f32>;
    var param_284: MxcClosure;
    var radiance: vec3<f32>;
    var lights: i32;
    var kinds: i32;
    var image: bool;
    var n_1: i32;
    var local_33: i32;
    var seed_2: u32;
    var param_285: u32;
    var param_286: u32;
    var param_287: u32;
    var pixel: u32;
    var param_288: u32;
    var param_289: u32;
    var shift: vec4<f32>;
    var param_290: u32;
    var param_291: u32;
    var param_292: u32;
    var param_293: u32;
    var sum: vec3<f32>;
    var b_4: i32;
    var batchLights: i32;
    var batchSamples: i32;
    var local_34: i32;
    var index: u32;
    var choice: vec4<f32>;
    var param_294: u32;
    var param_295: u32;
    var param_296: u32;
    var param_297: u32;
    var param_298: u32;
    var param_299: u32;
    var param_300: u32;
    var param_301: u32;
    var smp: MxcSample;
    var param_302: MxcClosure;
    var param_303: vec3<f32>;
    var param_304: vec3<f32>;
    var above_4: bool;
    var seen: vec3<f32>;
    var local_35: vec3<f32>;
    var local_36: vec3<f32>;
    var param_305: vec3<f32>;
    var param_306: vec3<f32>;
    var param_307: vec3<f32>;
    var w_1: f32;
    var local_37: f32;
    var param_308: vec3<f32>;
    var param_309: f32;
    var param_310: vec3<f32>;
    var param_311: f32;
    var param_312: f32;
    var m_8: vec3<f32>;
    var lightPdf: f32;
    var imageWi: vec3<f32>;
    var imageSeen: vec3<f32>;
    var v_8: vec4<f32>;
    var param_313: u32;
    var param_314: u32;
    var param_315: u32;
    var param_316: vec4<f32>;
    var param_317: f32;
    var param_318: vec3<f32>;
    var param_319: f32;
    var param_320: vec3<f32>;
    var j_2: i32;
    var wi_7: vec3<f32>;
    var incoming: vec3<f32>;
    var use_: bool;
    var strategy: i32;
    var local_38: i32;
    var light: vec4<f32>;
    var directional: bool;
    var param_321: vec3<f32>;
    var param_322: vec3<f32>;
    var d_8: vec3<f32>;
    var d2_: f32;
    var spot: vec4<f32>;
    var f_6: vec3<f32>;
    var pdf_2: f32;
    var param_323: MxcClosure;
    var param_324: vec3<f32>;
    var param_325: vec3<f32>;
    var param_326: bool;
    var param_327: f32;
    var w_2: f32;
    var local_39: f32;
    var param_328: vec3<f32>;
    var param_329: f32;
    var param_330: vec3<f32>;
    var param_331: f32;
    var param_332: f32;
    var w_3: f32;
    var param_333: vec3<f32>;
    var param_334: f32;
    var param_335: f32;
    var coverage: f32;
    var param_336: vec3<f32>;
    var phi_630_: bool;
    var phi_641_: bool;
    var phi_703_: bool;
    var phi_760_: bool;
    var phi_761_: bool;
    var phi_794_: bool;
    var phi_836_: bool;

    let _e247 = vPosition_1;
    g_2.P = _e247;
    let _e249 = vObjectPosition_1;
    g_2.Pobj = _e249;
    let _e251 = vNormal_1;
    param_268 = _e251;
    param_269 = vec3<f32>(0f, 0f, 1f);
    let _e252 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_268), (&param_269));
    N_1 = _e252;
    let _e253 = gl_FrontFacing_1;
    if !(_e253) {
        let _e255 = N_1;
        N_1 = -(_e255);
    }
    let _e258 = mxc_view.eye;
    let _e260 = vPosition_1;
    param_270 = (_e258.xyz - _e260);
    let _e262 = N_1;
    param_271 = _e262;
    let _e263 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_270), (&param_271));
    wo_20 = _e263;
    let _e264 = wo_20;
    let _e265 = N_1;
    facing = dot(_e264, _e265);
    let _e267 = facing;
    if (_e267 < 0.01f) {
        let _e269 = N_1;
        let _e270 = facing;
        let _e272 = wo_20;
        N_1 = normalize((_e269 + (_e272 * (0.01f - _e270))));
    }
    let _e277 = vTangent_1[3u];
    handedness = select(1f, -1f, (_e277 < 0f));
    let _e280 = N_1;
    param_272 = _e280;
    let _e281 = vTangent_1;
    param_273 = _e281.xyz;
    let _e283 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_272), (&param_273));
    frame_4 = _e283;
    let _e284 = N_1;
    g_2.N = _e284;
    let _e287 = frame_4[0];
    g_2.T = _e287;
    let _e290 = frame_4[1];
    let _e291 = handedness;
    g_2.B = (_e290 * _e291);
    let _e294 = vObjectNormal_1;
    param_274 = _e294;
    param_275 = vec3<f32>(0f, 0f, 1f);
    let _e295 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_274), (&param_275));
    g_2.Nobj = _e295;
    let _e298 = g_2.Nobj;
    param_276 = _e298;
    let _e299 = vObjectTangent_1;
    param_277 = _e299;
    let _e300 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_276), (&param_277));
    objectFrame = _e300;
    let _e302 = objectFrame[0];
    g_2.Tobj = _e302;
    let _e305 = objectFrame[1];
    let _e306 = handedness;
    g_2.Bobj = (_e305 * _e306);
    let _e309 = vUv_1;
    g_2.uv = _e309;
    g_2.color = vec4<f32>(1f, 1f, 1f, 1f);
    let _e313 = mxc_view.objectToWorld;
    g_2.objectToWorld = _e313;
    let _e316 = mxc_params.frame;
    g_2.frame = _e316;
    let _e319 = mxc_params.time;
    g_2.time = _e319;
    let _e322 = gl_FragCoord_1[0u];
    let _e325 = gl_FragCoord_1[1u];
    let _e329 = mxc_view.counts[2u];
    param_278 = (bitcast<u32>(_e329) + 7u);
    let _e332 = mxc_pcg_u0028_u1_u003b((&param_278));
    param_279 = (u32(_e325) + _e332);
    let _e334 = mxc_pcg_u0028_u1_u003b((&param_279));
    param_280 = (u32(_e322) ^ _e334);
    let _e336 = mxc_pcg_u0028_u1_u003b((&param_280));
    param_281 = _e336;
    mxc_closure_seed_u0028_u1_u003b((&param_281));
    let _e337 = g_2;
    param_282 = _e337;
    let _e338 = wo_20;
    param_283 = _e338;
    mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b((&param_282), (&param_283), (&param_284));
    let _e339 = param_284;
    c_10 = _e339;
    let _e341 = c_10.emission;
    let _e344 = mxc_view.environment[1u];
    radiance = (_e341 * _e344);
    let _e346 = mxc_light_count_u0028_();
    lights = _e346;
    let _e347 = mxc_light_kinds_u0028_();
    kinds = _e347;
    let _e348 = mxc_environment_code_u0028_();
    image = (_e348 == 3i);
    let _e350 = mxc_environment_code_u0028_();
    if (_e350 != 0i) {
        let _e354 = mxc_view.counts[3u];
        local_33 = max(_e354, 1i);
    } else {
        local_33 = 0i;
    }
    let _e356 = local_33;
    n_1 = _e356;
    let _e358 = gl_FragCoord_1[0u];
    let _e361 = gl_FragCoord_1[1u];
    let _e365 = mxc_view.counts[2u];
    param_285 = bitcast<u32>(_e365);
    let _e367 = mxc_pcg_u0028_u1_u003b((&param_285));
    param_286 = (u32(_e361) + _e367);
    let _e369 = mxc_pcg_u0028_u1_u003b((&param_286));
    param_287 = (u32(_e358) + _e369);
    let _e371 = mxc_pcg_u0028_u1_u003b((&param_287));
    seed_2 = _e371;
    let _e373 = gl_FragCoord_1[0u];
    let _e376 = gl_FragCoord_1[1u];
    param_288 = (u32(_e376) + 2654435769u);
    let _e379 = mxc_pcg_u0028_u1_u003b((&param_288));
    param_289 = (u32(_e373) ^ _e379);
    let _e381 = mxc_pcg_u0028_u1_u003b((&param_289));
    pixel = _e381;
    let _e382 = pixel;
    param_290 = _e382;
    let _e383 = mxc_uniform_u0028_u1_u003b((&param_290));
    let _e384 = param_290;
    pixel = _e384;
    let _e385 = pixel;
    param_291 = _e385;
    let _e386 = mxc_uniform_u0028_u1_u003b((&param_291));
    let _e387 = param_291;
    pixel = _e387;
    let _e388 = pixel;
    param_292 = _e388;
    let _e389 = mxc_uniform_u0028_u1_u003b((&param_292));
    let _e390 = param_292;
    pixel = _e390;
    let _e391 = pixel;
    param_293 = _e391;
    let _e392 = mxc_uniform_u0028_u1_u003b((&param_293));
    let _e393 = param_293;
    pixel = _e393;
    shift = vec4<f32>(_e383, _e386, _e389, _e392);
    sum = vec3<f32>(0f, 0f, 0f);
    b_4 = 0i;
    loop {
        let _e395 = b_4;
        let _e396 = n_1;
        let _e397 = lights;
        if (_e395 < max(_e396, select(0i, 1i, (_e397 > 0i)))) {
            let _e402 = b_4;
            let _e404 = lights;
            batchLights = select(0i, _e404, (_e402 == 0i));
            let _e406 = b_4;
            let _e407 = n_1;
            if (_e406 < _e407) {
                let _e409 = image;
                local_34 = (1i + select(0i, 1i, _e409));
            } else {
                local_34 = 0i;
            }
            let _e412 = local_34;
            batchSamples = _e412;
            let _e415 = mxc_view.counts[2u];
            let _e417 = n_1;
            let _e421 = b_4;
            index = ((bitcast<u32>(_e415) * bitcast<u32>(max(_e417, 1i))) + bitcast<u32>(_e421));
            let _e424 = index;
            param_294 = _e424;
            param_295 = 2u;
            let _e425 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_294), (&param_295));
            let _e426 = index;
            param_296 = _e426;
            param_297 = 3u;
            let _e427 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_296), (&param_297));
            let _e428 = index;
            param_298 = _e428;
            param_299 = 5u;
            let _e429 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_298), (&param_299));
            let _e430 = index;
            param_300 = _e430;
            param_301 = 7u;
            let _e431 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_300), (&param_301));
            let _e433 = shift;
            choice = fract((vec4<f32>(_e425, _e427, _e429, _e431) + _e433));
            smp.valid = false;
            smp.evaluate = false;
            smp.delta = false;
            smp.pdf = 0f;
            smp.weight = vec3<f32>(0f, 0f, 0f);
            let _e441 = N_1;
            smp.wi = _e441;
            let _e443 = n_1;
            if (_e443 > 0i) {
                let _e446 = choice[2u];
                let _e448 = choice[3u];
                let _e450 = choice[0u];
                let _e452 = c_10;
                param_302 = _e452;
                let _e453 = wo_20;
                param_303 = _e453;
                param_304 = vec3<f32>(_e446, _e448, _e450);
                let _e454 = mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b((&param_302), (&param_303), (&param_304));
                smp = _e454;
            }
            let _e456 = smp.wi;
            let _e457 = N_1;
            above_4 = (dot(_e456, _e457) > 0f);
            let _e461 = smp.valid;
            if _e461 {
                let _e462 = above_4;
                if _e462 {
                    let _e464 = smp.wi;
                    local_36 = _e464;
                } else {
                    let _e465 = wo_20;
                    param_305 = -(_e465);
                    let _e468 = smp.wi;
                    param_306 = _e468;
                    let _e469 = mxc_exit_direction_u0028_vf3_u003b_vf3_u003b((&param_305), (&param_306));
                    local_36 = _e469;
                }
                let _e470 = local_36;
                param_307 = _e470;
                let _e471 = mxc_environment_u0028_vf3_u003b((&param_307));
                local_35 = _e471;
            } else {
                local_35 = vec3<f32>(0f, 0f, 0f);
            }
            let _e472 = local_35;
            seen = _e472;
            let _e473 = b_4;
            let _e474 = n_1;
            let _e477 = smp.valid;
            let _e478 = ((_e473 < _e474) && _e477);
            phi_630_ = _e478;
            if _e478 {
                let _e480 = smp.evaluate;
                phi_630_ = !(_e480);
            }
            let _e483 = phi_630_;
            if _e483 {
                let _e484 = image;
                let _e485 = above_4;
                let _e486 = (_e484 && _e485);
                phi_641_ = _e486;
                if _e486 {
                    let _e488 = smp.delta;
                    phi_641_ = !(_e488);
                }
                let _e491 = phi_641_;
                if _e491 {
                    let _e493 = smp.wi;
                    param_308 = _e493;
                    let _e496 = mxc_view.environment[2u];
                    param_309 = _e496;
                    let _e497 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_308), (&param_309));
                    param_310 = _e497;
                    let _e498 = mxc_env_pdf_u0028_vf3_u003b((&param_310));
                    let _e500 = smp.pdf;
                    param_311 = _e500;
                    param_312 = _e498;
                    let _e501 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_311), (&param_312));
                    local_37 = _e501;
                } else {
                    local_37 = 1f;
                }
                let _e502 = local_37;
                w_1 = _e502;
                let _e503 = w_1;
                let _e505 = smp.weight;
                let _e507 = seen;
                let _e509 = sum;
                sum = (_e509 + ((_e505 * _e503) * _e507));
            }
            m_8 = vec3<f32>(0f, 0f, 0f);
            lightPdf = 0f;
            let _e511 = N_1;
            imageWi = _e511;
            imageSeen = vec3<f32>(0f, 0f, 0f);
            let _e512 = image;
            let _e513 = b_4;
            let _e514 = n_1;
            if (_e512 && (_e513 < _e514)) {
                let _e518 = choice[1u];
                let _e519 = seed_2;
                param_313 = _e519;
                let _e520 = mxc_uniform_u0028_u1_u003b((&param_313));
                let _e521 = param_313;
                seed_2 = _e521;
                let _e522 = seed_2;
                param_314 = _e522;
                let _e523 = mxc_uniform_u0028_u1_u003b((&param_314));
                let _e524 = param_314;
                seed_2 = _e524;
                let _e525 = seed_2;
                param_315 = _e525;
                let _e526 = mxc_uniform_u0028_u1_u003b((&param_315));
                let _e527 = param_315;
                seed_2 = _e527;
                v_8 = vec4<f32>(_e518, _e520, _e523, _e526);
                let _e529 = v_8;
                param_316 = _e529;
                let _e530 = mxc_env_sample_u0028_vf4_u003b_f1_u003b((&param_316), (&param_317));
                let _e531 = param_317;
                lightPdf = _e531;
                m_8 = _e530;
                let _e532 = m_8;
                param_318 = _e532;
                let _e535 = mxc_view.environment[2u];
                param_319 = _e535;
                let _e536 = mxc_env_to_world_u0028_vf3_u003b_f1_u003b((&param_318), (&param_319));
                imageWi = _e536;
                let _e537 = lightPdf;
                let _e538 = (_e537 > 0f);
                phi_703_ = _e538;
                if _e538 {
                    let _e539 = imageWi;
                    let _e540 = N_1;
                    phi_703_ = (dot(_e539, _e540) > 0f);
                }
                let _e544 = phi_703_;
                if _e544 {
                    let _e545 = imageWi;
                    param_320 = _e545;
                    let _e546 = mxc_environment_u0028_vf3_u003b((&param_320));
                    imageSeen = _e546;
                }
            }
            j_2 = 0i;
            loop {
                let _e547 = j_2;
                let _e548 = batchLights;
                let _e549 = batchSamples;
                if (_e547 < (_e548 + _e549)) {
                    let _e552 = N_1;
                    wi_7 = _e552;
                    incoming = vec3<f32>(0f, 0f, 0f);
                    use_ = true;
                    let _e553 = n_1;
                    let _e555 = j_2;
                    let _e556 = batchLights;
                    if ((_e553 == 0i) || (_e555 < _e556)) {
                        local_38 = 0i;
                    } else {
                        let _e559 = j_2;
                        let _e560 = batchLights;
                        local_38 = select(2i, 1i, (_e559 == ((_e560 + 1i) - 1i)));
                    }
                    let _e565 = local_38;
                    strategy = _e565;
                    let _e566 = strategy;
                    if (_e566 == 0i) {
                        let _e568 = j_2;
                        let _e571 = mxc_view.lightVector[_e568];
                        light = _e571;
                        let _e572 = j_2;
                        let _e575 = mxc_view.lightRadiance[_e572];
                        incoming = _e575.xyz;
                        let _e577 = kinds;
                        let _e578 = (_e577 == 1i);
                        phi_761_ = _e578;
                        if !(_e578) {
                            let _e580 = kinds;
                            let _e582 = ((_e580 & 1i) != 0i);
                            phi_760_ = _e582;
                            if _e582 {
                                let _e584 = light[3u];
                                phi_760_ = (_e584 == 0f);
                            }
                            let _e587 = phi_760_;
                            phi_761_ = _e587;
                        }
                        let _e589 = phi_761_;
                        directional = _e589;
                        let _e590 = directional;
                        if _e590 {
                            let _e591 = light;
                            param_321 = _e591.xyz;
                            let _e593 = N_1;
                            param_322 = _e593;
                            let _e594 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_321), (&param_322));
                            wi_7 = _e594;
                        } else {
                            let _e595 = light;
                            let _e597 = vPosition_1;
                            d_8 = (_e595.xyz - _e597);
                            let _e599 = d_8;
                            let _e600 = d_8;
                            d2_ = max(dot(_e599, _e600), 0.00000001f);
                            let _e603 = d_8;
                            let _e604 = d2_;
                            wi_7 = (_e603 * inverseSqrt(_e604));
                            let _e607 = d2_;
                            let _e608 = incoming;
                            incoming = (_e608 / vec3(_e607));
                            let _e611 = kinds;
                            let _e613 = ((_e611 & 4i) != 0i);
                            phi_794_ = _e613;
                            if _e613 {
                                let _e615 = light[3u];
                                phi_794_ = (_e615 == 2f);
                            }
                            let _e618 = phi_794_;
                            if _e618 {
                                let _e619 = j_2;
                                let _e622 = mxc_view.lightSpot[_e619];
                                spot = _e622;
                                let _e624 = spot[3u];
                                let _e625 = j_2;
                                let _e629 = mxc_view.lightRadiance[_e625][3u];
                                let _e630 = wi_7;
                                let _e632 = spot;
                                let _e636 = incoming;
                                incoming = (_e636 * smoothstep(_e624, _e629, dot(-(_e630), _e632.xyz)));
                            }
                        }
                    } else {
                        let _e638 = strategy;
                        if (_e638 == 1i) {
                            let _e641 = smp.wi;
                            wi_7 = _e641;
                            let _e642 = seen;
                            incoming = _e642;
                            let _e644 = smp.valid;
                            let _e646 = smp.evaluate;
                            use_ = (_e644 && _e646);
                        } else {
                            let _e648 = imageWi;
                            wi_7 = _e648;
                            let _e649 = imageSeen;
                            incoming = _e649;
                            let _e650 = lightPdf;
                            let _e651 = (_e650 > 0f);
                            phi_836_ = _e651;
                            if _e651 {
                                let _e652 = imageWi;
                                let _e653 = N_1;
                                phi_836_ = (dot(_e652, _e653) > 0f);
                            }
                            let _e657 = phi_836_;
                            use_ = _e657;
                        }
                    }
                    let _e658 = strategy;
                    let _e660 = c_10;
                    param_323 = _e660;
                    let _e661 = wo_20;
                    param_324 = _e661;
                    let _e662 = wi_7;
                    param_325 = _e662;
                    param_326 = (_e658 != 0i);
                    let _e663 = mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b((&param_323), (&param_324), (&param_325), (&param_326), (&param_327));
                    let _e664 = param_327;
                    pdf_2 = _e664;
                    f_6 = _e663;
                    let _e665 = strategy;
                    if (_e665 == 0i) {
                        let _e667 = f_6;
                        let _e668 = incoming;
                        let _e670 = radiance;
                        radiance = (_e670 + (_e667 * _e668));
                    } else {
                        let _e672 = strategy;
                        if (_e672 == 1i) {
                            let _e674 = use_;
                            let _e675 = pdf_2;
                            if (_e674 && (_e675 > 0f)) {
                                let _e678 = image;
                                let _e679 = above_4;
                                if (_e678 && _e679) {
                                    let _e681 = wi_7;
                                    param_328 = _e681;
                                    let _e684 = mxc_view.environment[2u];
                                    param_329 = _e684;
                                    let _e685 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_328), (&param_329));
                                    param_330 = _e685;
                                    let _e686 = mxc_env_pdf_u0028_vf3_u003b((&param_330));
                                    let _e687 = pdf_2;
                                    param_331 = _e687;
                                    param_332 = _e686;
                                    let _e688 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_331), (&param_332));
                                    local_39 = _e688;
                                } else {
                                    local_39 = 1f;
                                }
                                let _e689 = local_39;
                                w_2 = _e689;
                                let _e690 = w_2;
                                let _e691 = f_6;
                                let _e693 = pdf_2;
                                let _e696 = incoming;
                                let _e698 = sum;
                                sum = (_e698 + (((_e691 * _e690) / vec3(_e693)) * _e696));
                            }
                        } else {
                            let _e700 = use_;
                            if _e700 {
                                let _e701 = m_8;
                                param_333 = _e701;
                                let _e702 = mxc_env_pdf_u0028_vf3_u003b((&param_333));
                                param_334 = _e702;
                                let _e703 = pdf_2;
                                param_335 = _e703;
                                let _e704 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_334), (&param_335));
                                w_3 = _e704;
                                let _e705 = w_3;
                                let _e706 = f_6;
                                let _e708 = incoming;
                                let _e710 = lightPdf;
                                let _e713 = sum;
                                sum = (_e713 + (((_e706 * _e705) * _e708) / vec3(_e710)));
                            }
                        }
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e715 = j_2;
                    j_2 = (_e715 + 1i);
                }
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e717 = b_4;
            b_4 = (_e717 + 1i);
        }
    }
    let _e719 = sum;
    let _e720 = n_1;
    let _e725 = radiance;
    radiance = (_e725 + (_e719 / vec3(f32(max(_e720, 1i)))));
    let _e728 = c_10.transparency;
    param_336 = _e728;
    let _e729 = mxc_luminance_u0028_vf3_u003b((&param_336));
    coverage = (1f - clamp(_e729, 0f, 1f));
    let _e732 = radiance;
    let _e733 = coverage;
    outColor = vec4<f32>(_e732.x, _e732.y, _e732.z, _e733);
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
