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
    let _e143 = (*c);
    return dot(_e143, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l: ptr<function, MxcLobe>) -> bool {
    return false;
}

fn mxc_mean_u0028_vf3_u003b(c_1: ptr<function, vec3<f32>>) -> f32 {
    let _e144 = (*c_1)[0u];
    let _e146 = (*c_1)[1u];
    let _e149 = (*c_1)[2u];
    return (((_e144 + _e146) + _e149) * 0.33333334f);
}

fn mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b(cosi: ptr<function, f32>, eta: ptr<function, f32>) -> f32 {
    var sin2t: f32;
    var cost: f32;
    var rs: f32;
    var rp: f32;

    let _e148 = (*eta);
    if (abs((_e148 - 1f)) < 0.000001f) {
        return 0f;
    }
    let _e152 = (*cosi);
    let _e153 = (*cosi);
    let _e156 = (*eta);
    let _e157 = (*eta);
    sin2t = ((1f - (_e152 * _e153)) / (_e156 * _e157));
    let _e160 = sin2t;
    if (_e160 >= 1f) {
        return 1f;
    }
    let _e162 = sin2t;
    cost = sqrt((1f - _e162));
    let _e165 = (*cosi);
    let _e166 = (*eta);
    let _e167 = cost;
    let _e170 = (*cosi);
    let _e171 = (*eta);
    let _e172 = cost;
    rs = ((_e165 - (_e166 * _e167)) / (_e170 + (_e171 * _e172)));
    let _e176 = (*eta);
    let _e177 = (*cosi);
    let _e179 = cost;
    let _e181 = (*eta);
    let _e182 = (*cosi);
    let _e184 = cost;
    rp = (((_e176 * _e177) - _e179) / ((_e181 * _e182) + _e184));
    let _e187 = rs;
    let _e188 = rs;
    let _e190 = rp;
    let _e191 = rp;
    return (0.5f * ((_e187 * _e188) + (_e190 * _e191)));
}

fn mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_1: ptr<function, MxcLobe>, above: ptr<function, bool>) -> f32 {
    var local: f32;

    let _e145 = (*above);
    if _e145 {
        let _e147 = (*l_1).eta;
        local = _e147;
    } else {
        let _e149 = (*l_1).eta;
        local = (1f / _e149);
    }
    let _e151 = local;
    return _e151;
}

fn mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b(l_2: ptr<function, MxcLobe>, cosh_: ptr<function, f32>, above_1: ptr<function, bool>) -> vec3<f32> {
    var f: vec3<f32>;
    var param: MxcLobe;
    var param_1: bool;
    var param_2: f32;
    var param_3: f32;

    f = vec3<f32>(1f, 1f, 1f);
    let _e151 = (*l_2).kind;
    if (_e151 == 1i) {
        let _e153 = (*l_2);
        param = _e153;
        let _e154 = (*above_1);
        param_1 = _e154;
        let _e155 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param), (&param_1));
        let _e156 = (*cosh_);
        param_2 = _e156;
        param_3 = _e155;
        let _e157 = mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b((&param_2), (&param_3));
        f = vec3(_e157);
    }
    let _e159 = f;
    return _e159;
}

fn mxc_rough_alpha_u0028_vf2_u003b(alpha: ptr<function, vec2<f32>>) -> vec2<f32> {
    let _e143 = (*alpha);
    return max(_e143, vec2<f32>(0.0001f, 0.0001f));
}

fn mxc_ggx_d_u0028_vf3_u003b_vf2_u003b(m: ptr<function, vec3<f32>>, alpha_1: ptr<function, vec2<f32>>) -> f32 {
    var param_4: vec2<f32>;
    var s: vec3<f32>;
    var d: f32;

    let _e148 = (*m)[2u];
    if (_e148 <= 0f) {
        return 0f;
    }
    let _e150 = (*alpha_1);
    param_4 = _e150;
    let _e151 = mxc_rough_alpha_u0028_vf2_u003b((&param_4));
    (*alpha_1) = _e151;
    let _e153 = (*m)[0u];
    let _e155 = (*alpha_1)[0u];
    let _e158 = (*m)[1u];
    let _e160 = (*alpha_1)[1u];
    let _e163 = (*m)[2u];
    s = vec3<f32>((_e153 / _e155), (_e158 / _e160), _e163);
    let _e165 = s;
    let _e166 = s;
    d = dot(_e165, _e166);
    let _e169 = (*alpha_1)[0u];
    let _e172 = (*alpha_1)[1u];
    let _e174 = d;
    let _e176 = d;
    return (1f / ((((3.1415927f * _e169) * _e172) * _e174) * _e176));
}

fn mxc_sqr_u0028_f1_u003b(x: ptr<function, f32>) -> f32 {
    let _e143 = (*x);
    let _e144 = (*x);
    return (_e143 * _e144);
}

fn mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b(v: ptr<function, vec3<f32>>, alpha_2: ptr<function, vec2<f32>>) -> f32 {
    var param_5: vec2<f32>;
    var z2_: f32;
    var a2_: f32;
    var param_6: f32;
    var param_7: f32;

    let _e149 = (*alpha_2);
    param_5 = _e149;
    let _e150 = mxc_rough_alpha_u0028_vf2_u003b((&param_5));
    (*alpha_2) = _e150;
    let _e152 = (*v)[2u];
    let _e154 = (*v)[2u];
    z2_ = (_e152 * _e154);
    let _e156 = z2_;
    if (_e156 <= 0f) {
        return 10000000000f;
    }
    let _e159 = (*alpha_2)[0u];
    let _e161 = (*v)[0u];
    param_6 = (_e159 * _e161);
    let _e163 = mxc_sqr_u0028_f1_u003b((&param_6));
    let _e165 = (*alpha_2)[1u];
    let _e167 = (*v)[1u];
    param_7 = (_e165 * _e167);
    let _e169 = mxc_sqr_u0028_f1_u003b((&param_7));
    let _e171 = z2_;
    a2_ = ((_e163 + _e169) / _e171);
    let _e173 = a2_;
    return (0.5f * (-1f + sqrt((1f + _e173))));
}

fn mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b(v_1: ptr<function, vec3<f32>>, alpha_3: ptr<function, vec2<f32>>) -> f32 {
    var param_8: vec3<f32>;
    var param_9: vec2<f32>;

    let _e146 = (*v_1);
    param_8 = _e146;
    let _e147 = (*alpha_3);
    param_9 = _e147;
    let _e148 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_8), (&param_9));
    return (1f / (1f + _e148));
}

fn mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo: ptr<function, vec3<f32>>, m_1: ptr<function, vec3<f32>>, alpha_4: ptr<function, vec2<f32>>) -> f32 {
    var param_10: vec3<f32>;
    var param_11: vec2<f32>;
    var param_12: vec3<f32>;
    var param_13: vec2<f32>;

    let _e150 = (*wo)[2u];
    if (_e150 <= 0f) {
        return 0f;
    }
    let _e152 = (*wo);
    param_10 = _e152;
    let _e153 = (*alpha_4);
    param_11 = _e153;
    let _e154 = mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b((&param_10), (&param_11));
    let _e155 = (*wo);
    let _e156 = (*m_1);
    let _e160 = (*m_1);
    param_12 = _e160;
    let _e161 = (*alpha_4);
    param_13 = _e161;
    let _e162 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_12), (&param_13));
    let _e165 = (*wo)[2u];
    return (((_e154 * max(dot(_e155, _e156), 0f)) * _e162) / _e165);
}

fn mxc_is_delta_u0028_vf2_u003b(alpha_5: ptr<function, vec2<f32>>) -> bool {
    let _e144 = (*alpha_5)[0u];
    let _e146 = (*alpha_5)[1u];
    return (max(_e144, _e146) < 0.0001f);
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
    var phi_2512_: bool;
    var phi_2593_: bool;

    let _e164 = (*l_3).kind;
    switch _e164 {
        case 2, 3, 1: {
            let _e178 = (*l_3).alpha;
            param_14 = _e178;
            let _e179 = mxc_is_delta_u0028_vf2_u003b((&param_14));
            if _e179 {
                return 0f;
            }
            let _e181 = (*wo_1)[2u];
            above_2 = (_e181 > 0f);
            let _e183 = above_2;
            if _e183 {
                let _e184 = (*wo_1);
                local_1 = _e184;
            } else {
                let _e185 = (*wo_1);
                local_1 = -(_e185);
            }
            let _e187 = local_1;
            o = _e187;
            let _e188 = above_2;
            if _e188 {
                let _e189 = (*wi);
                local_2 = _e189;
            } else {
                let _e190 = (*wi);
                local_2 = -(_e190);
            }
            let _e192 = local_2;
            i = _e192;
            let _e194 = i[2u];
            if (_e194 > 0f) {
                let _e196 = o;
                let _e197 = i;
                h = normalize((_e196 + _e197));
                let _e200 = o;
                param_15 = _e200;
                let _e201 = h;
                param_16 = _e201;
                let _e203 = (*l_3).alpha;
                param_17 = _e203;
                let _e204 = mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_15), (&param_16), (&param_17));
                let _e205 = o;
                let _e206 = h;
                p = (_e204 / (4f * max(dot(_e205, _e206), 0.000001f)));
                let _e212 = (*l_3).kind;
                if (_e212 == 2i) {
                    let _e214 = p;
                    return _e214;
                }
                let _e216 = (*l_3).mode;
                if ((_e216 & 1i) == 0i) {
                    return 0f;
                }
                let _e219 = o;
                let _e220 = h;
                let _e223 = (*l_3);
                param_18 = _e223;
                param_19 = max(dot(_e219, _e220), 0f);
                let _e224 = above_2;
                param_20 = _e224;
                let _e225 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_18), (&param_19), (&param_20));
                param_21 = _e225;
                let _e226 = mxc_mean_u0028_vf3_u003b((&param_21));
                fr = _e226;
                let _e227 = p;
                let _e228 = (*l_3);
                param_22 = _e228;
                let _e229 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_22));
                phi_2593_ = _e229;
                if _e229 {
                    let _e231 = (*l_3).mode;
                    phi_2593_ = ((_e231 & 1i) != 0i);
                }
                let _e235 = phi_2593_;
                let _e236 = fr;
                return (_e227 * select(1f, _e236, _e235));
            }
            return 0f;
        }
        default: {
            let _e166 = (*wo_1)[2u];
            let _e167 = (_e166 > 0f);
            phi_2512_ = _e167;
            if _e167 {
                let _e169 = (*wi)[2u];
                phi_2512_ = (_e169 > 0f);
            }
            let _e172 = phi_2512_;
            if _e172 {
                let _e174 = (*wi)[2u];
                local_3 = (_e174 * 0.31830987f);
            } else {
                local_3 = 0f;
            }
            let _e176 = local_3;
            return _e176;
        }
    }
}

fn mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b(sigma: ptr<function, f32>, wo_2: ptr<function, vec3<f32>>, wi_1: ptr<function, vec3<f32>>) -> f32 {
    var a: f32;
    var s_1: f32;
    var t: f32;
    var local_4: f32;

    let _e149 = (*sigma);
    a = (1f / (1f + (0.2877934f * _e149)));
    let _e153 = (*wi_1);
    let _e154 = (*wo_2);
    let _e157 = (*wi_1)[2u];
    let _e159 = (*wo_2)[2u];
    s_1 = (dot(_e153, _e154) - (_e157 * _e159));
    let _e162 = s_1;
    if (_e162 > 0f) {
        let _e165 = (*wi_1)[2u];
        let _e167 = (*wo_2)[2u];
        local_4 = max(max(_e165, _e167), 0.000001f);
    } else {
        local_4 = 1f;
    }
    let _e170 = local_4;
    t = _e170;
    let _e171 = a;
    let _e172 = (*sigma);
    let _e173 = a;
    let _e175 = s_1;
    let _e177 = t;
    return ((_e171 + (((_e172 * _e173) * _e175) / _e177)) * 0.31830987f);
}

fn mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo_3: ptr<function, vec3<f32>>, wi_2: ptr<function, vec3<f32>>, alpha_6: ptr<function, vec2<f32>>) -> f32 {
    var param_23: vec3<f32>;
    var param_24: vec2<f32>;
    var param_25: vec3<f32>;
    var param_26: vec2<f32>;

    let _e149 = (*wo_3);
    param_23 = _e149;
    let _e150 = (*alpha_6);
    param_24 = _e150;
    let _e151 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_23), (&param_24));
    let _e153 = (*wi_2);
    param_25 = _e153;
    let _e154 = (*alpha_6);
    param_26 = _e154;
    let _e155 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_25), (&param_26));
    return (1f / ((1f + _e151) + _e155));
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
    var phi_1914_: bool;
    var phi_1921_: bool;

    let _e157 = (*wo_4)[2u];
    let _e158 = (_e157 <= 0f);
    phi_1914_ = _e158;
    if !(_e158) {
        let _e161 = (*wi_3)[2u];
        phi_1914_ = (_e161 <= 0f);
    }
    let _e164 = phi_1914_;
    phi_1921_ = _e164;
    if !(_e164) {
        let _e167 = (*l_4).alpha;
        param_27 = _e167;
        let _e168 = mxc_is_delta_u0028_vf2_u003b((&param_27));
        phi_1921_ = _e168;
    }
    let _e170 = phi_1921_;
    if _e170 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e171 = (*wo_4);
    let _e172 = (*wi_3);
    h_1 = normalize((_e171 + _e172));
    let _e175 = (*wo_4);
    let _e176 = h_1;
    let _e179 = (*l_4);
    param_28 = _e179;
    param_29 = max(dot(_e175, _e176), 0f);
    param_30 = true;
    let _e180 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_28), (&param_29), (&param_30));
    f_1 = _e180;
    let _e182 = (*l_4).kind;
    if (_e182 == 1i) {
        let _e185 = (*l_4).c0_;
        let _e186 = f_1;
        f_1 = (_e186 * _e185);
    }
    let _e188 = f_1;
    let _e189 = h_1;
    param_31 = _e189;
    let _e191 = (*l_4).alpha;
    param_32 = _e191;
    let _e192 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_31), (&param_32));
    let _e194 = (*wo_4);
    param_33 = _e194;
    let _e195 = (*wi_3);
    param_34 = _e195;
    let _e197 = (*l_4).alpha;
    param_35 = _e197;
    let _e198 = mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_33), (&param_34), (&param_35));
    let _e201 = (*wo_4)[2u];
    return (((_e188 * _e192) * _e198) / vec3((4f * _e201)));
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
    var phi_2445_: bool;
    var phi_2460_: bool;

    let _e160 = (*l_5).kind;
    switch _e160 {
        case 1: {
            let _e162 = (*wo_5)[2u];
            let _e164 = (*wi_4)[2u];
            if ((_e162 * _e164) > 0f) {
                let _e168 = (*l_5).mode;
                if ((_e168 & 1i) == 0i) {
                    return vec3<f32>(0f, 0f, 0f);
                }
                let _e172 = (*wo_5)[2u];
                if (_e172 < 0f) {
                    let _e174 = (*l_5);
                    m_2 = _e174;
                    let _e176 = (*l_5).eta;
                    m_2.eta = (1f / _e176);
                    m_2.c0_ = vec3<f32>(1f, 1f, 1f);
                    let _e180 = (*wo_5);
                    let _e182 = (*wi_4);
                    let _e184 = m_2;
                    param_36 = _e184;
                    param_37 = -(_e180);
                    param_38 = -(_e182);
                    let _e185 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_36), (&param_37), (&param_38));
                    return _e185;
                }
                let _e186 = (*l_5);
                param_39 = _e186;
                let _e187 = (*wo_5);
                param_40 = _e187;
                let _e188 = (*wi_4);
                param_41 = _e188;
                let _e189 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_39), (&param_40), (&param_41));
                return _e189;
            }
            return vec3<f32>(0f, 0f, 0f);
        }
        case 3, 2: {
            let _e191 = (*l_5).kind;
            let _e192 = (_e191 == 3i);
            phi_2445_ = _e192;
            if _e192 {
                let _e194 = (*l_5).mode;
                phi_2445_ = ((_e194 & 1i) == 0i);
            }
            let _e198 = phi_2445_;
            if _e198 {
                return vec3<f32>(0f, 0f, 0f);
            }
            let _e199 = (*l_5);
            param_42 = _e199;
            let _e200 = (*wo_5);
            param_43 = _e200;
            let _e201 = (*wi_4);
            param_44 = _e201;
            let _e202 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_42), (&param_43), (&param_44));
            return _e202;
        }
        case 4: {
            let _e204 = (*wo_5)[2u];
            let _e205 = (_e204 > 0f);
            phi_2460_ = _e205;
            if _e205 {
                let _e207 = (*wi_4)[2u];
                phi_2460_ = (_e207 > 0f);
            }
            let _e210 = phi_2460_;
            if _e210 {
                let _e212 = (*l_5).c0_;
                let _e214 = (*l_5).p0_;
                param_45 = _e214;
                let _e215 = (*wo_5);
                param_46 = _e215;
                let _e216 = (*wi_4);
                param_47 = _e216;
                let _e217 = mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b((&param_45), (&param_46), (&param_47));
                let _e220 = (*wi_4)[2u];
                local_5 = ((_e212 * _e217) * _e220);
            } else {
                local_5 = vec3<f32>(0f, 0f, 0f);
            }
            let _e222 = local_5;
            return _e222;
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
    let _e144 = (*v_2);
    let _e146 = (*frame)[0];
    let _e148 = (*v_2);
    let _e150 = (*frame)[1];
    let _e152 = (*v_2);
    let _e154 = (*frame)[2];
    return vec3<f32>(dot(_e144, _e146), dot(_e148, _e150), dot(_e152, _e154));
}

fn mxc_frame_u0028_vf3_u003b_vf3_u003b(N: ptr<function, vec3<f32>>, T: ptr<function, vec3<f32>>) -> mat3x3<f32> {
    var t_1: vec3<f32>;
    var l2_: f32;
    var s_2: f32;
    var a_1: f32;
    var b: f32;

    let _e149 = (*T);
    let _e150 = (*N);
    let _e151 = (*N);
    let _e152 = (*T);
    t_1 = (_e149 - (_e150 * dot(_e151, _e152)));
    let _e156 = t_1;
    let _e157 = t_1;
    l2_ = dot(_e156, _e157);
    let _e159 = l2_;
    if !((_e159 > 0.000000000001f)) {
        let _e163 = (*N)[2u];
        s_2 = select(-1f, 1f, (_e163 >= 0f));
        let _e166 = s_2;
        let _e168 = (*N)[2u];
        a_1 = (-1f / (_e166 + _e168));
        let _e172 = (*N)[0u];
        let _e174 = (*N)[1u];
        let _e176 = a_1;
        b = ((_e172 * _e174) * _e176);
        let _e178 = s_2;
        let _e180 = (*N)[0u];
        let _e183 = (*N)[0u];
        let _e185 = a_1;
        let _e188 = s_2;
        let _e189 = b;
        let _e191 = s_2;
        let _e194 = (*N)[0u];
        t_1 = vec3<f32>((1f + (((_e178 * _e180) * _e183) * _e185)), (_e188 * _e189), (-(_e191) * _e194));
    } else {
        let _e197 = l2_;
        let _e199 = t_1;
        t_1 = (_e199 * inverseSqrt(_e197));
    }
    let _e201 = t_1;
    let _e202 = (*N);
    let _e203 = t_1;
    let _e204 = cross(_e202, _e203);
    let _e205 = (*N);
    return mat3x3<f32>(vec3<f32>(_e201.x, _e201.y, _e201.z), vec3<f32>(_e204.x, _e204.y, _e204.z), vec3<f32>(_e205.x, _e205.y, _e205.z));
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
        let _e169 = k;
        let _e171 = (*c_2).count;
        if (_e169 < _e171) {
            let _e173 = k;
            let _e176 = (*c_2).lobes[_e173];
            l_7 = _e176;
            let _e178 = l_7.weight;
            if all((_e178 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e182 = l_7.N;
            param_48 = _e182;
            let _e184 = l_7.T;
            param_49 = _e184;
            let _e185 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_48), (&param_49));
            frame_1 = _e185;
            let _e186 = frame_1;
            param_50 = _e186;
            let _e187 = (*wo_6);
            param_51 = _e187;
            let _e188 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_50), (&param_51));
            o_1 = _e188;
            let _e189 = frame_1;
            param_52 = _e189;
            let _e190 = (*wi_5);
            param_53 = _e190;
            let _e191 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_52), (&param_53));
            i_1 = _e191;
            let _e193 = l_7.weight;
            let _e194 = k;
            let _e197 = (*c_2).ms[_e194];
            let _e200 = i_1[2u];
            let _e202 = l_7;
            param_54 = _e202;
            param_55 = abs(_e200);
            let _e203 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_54), (&param_55));
            let _e205 = l_7;
            param_56 = _e205;
            let _e206 = o_1;
            param_57 = _e206;
            let _e207 = i_1;
            param_58 = _e207;
            let _e208 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_56), (&param_57), (&param_58));
            let _e210 = f_2;
            f_2 = (_e210 + (((_e193 * _e197) * _e203) * _e208));
            let _e212 = (*wantPdf);
            if _e212 {
                let _e213 = k;
                let _e216 = (*c_2).choice[_e213];
                let _e217 = l_7;
                param_59 = _e217;
                let _e218 = o_1;
                param_60 = _e218;
                let _e219 = i_1;
                param_61 = _e219;
                let _e220 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_59), (&param_60), (&param_61));
                let _e222 = p_1;
                p_1 = (_e222 + (_e216 * _e220));
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e224 = k;
            k = (_e224 + 1i);
        }
    }
    let _e227 = (*c_2).choiceTotal;
    if (_e227 > 0f) {
        let _e229 = p_1;
        let _e231 = (*c_2).choiceTotal;
        local_6 = (_e229 / _e231);
    } else {
        local_6 = 0f;
    }
    let _e233 = local_6;
    (*pdf) = _e233;
    let _e234 = f_2;
    return _e234;
}

fn mxc_env_to_world_u0028_vf3_u003b_f1_u003b(m_3: ptr<function, vec3<f32>>, angle: ptr<function, f32>) -> vec3<f32> {
    var c_3: f32;
    var s_3: f32;

    let _e146 = (*angle);
    c_3 = cos(_e146);
    let _e148 = (*angle);
    s_3 = sin(_e148);
    let _e150 = c_3;
    let _e152 = (*m_3)[0u];
    let _e154 = s_3;
    let _e156 = (*m_3)[2u];
    let _e160 = (*m_3)[1u];
    let _e161 = s_3;
    let _e164 = (*m_3)[0u];
    let _e166 = c_3;
    let _e168 = (*m_3)[2u];
    return vec3<f32>(((_e150 * _e152) + (_e154 * _e156)), _e160, ((-(_e161) * _e164) + (_e166 * _e168)));
}

fn mxc_safe_sqrt_u0028_f1_u003b(x_1: ptr<function, f32>) -> f32 {
    let _e143 = (*x_1);
    return sqrt(max(_e143, 0f));
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

    let _e157 = unnamed.mxc_env_size;
    size = max(_e157.xy, vec2<u32>(1u, 1u));
    let _e161 = size[0u];
    let _e163 = size[1u];
    n = (_e161 * _e163);
    let _e166 = (*u)[0u];
    let _e167 = n;
    let _e171 = n;
    k_1 = min(u32((_e166 * f32(_e167))), (_e171 - 1u));
    let _e174 = k_1;
    let _e177 = unnamed.mxc_env_cells[_e174];
    cell = _e177;
    let _e179 = (*u)[1u];
    let _e181 = cell[0u];
    if (_e179 >= _e181) {
        let _e184 = cell[1u];
        let _e186 = n;
        k_1 = min(bitcast<u32>(_e184), (_e186 - 1u));
    }
    let _e189 = k_1;
    let _e193 = unnamed.mxc_env_cells[_e189][2u];
    (*pdf_1) = _e193;
    let _e194 = k_1;
    let _e196 = size[0u];
    i_2 = (_e194 % _e196);
    let _e198 = k_1;
    let _e200 = size[0u];
    j = (_e198 / _e200);
    let _e202 = i_2;
    let _e205 = (*u)[2u];
    let _e208 = size[0u];
    phi = (6.2831855f * (((f32(_e202) + _e205) / f32(_e208)) - 0.5f));
    let _e213 = j;
    let _e217 = size[1u];
    y0_ = cos(((3.1415927f * f32(_e213)) / f32(_e217)));
    let _e221 = j;
    let _e226 = size[1u];
    y1_ = cos(((3.1415927f * f32((_e221 + 1u))) / f32(_e226)));
    let _e230 = y0_;
    let _e231 = y1_;
    let _e233 = (*u)[3u];
    y = mix(_e230, _e231, _e233);
    let _e235 = y;
    let _e236 = y;
    param_62 = (1f - (_e235 * _e236));
    let _e239 = mxc_safe_sqrt_u0028_f1_u003b((&param_62));
    r = _e239;
    let _e240 = r;
    let _e241 = phi;
    let _e244 = y;
    let _e245 = r;
    let _e247 = phi;
    return vec3<f32>((_e240 * sin(_e241)), _e244, (-(_e245) * cos(_e247)));
}

fn mxc_power_heuristic_u0028_f1_u003b_f1_u003b(a_2: ptr<function, f32>, b_1: ptr<function, f32>) -> f32 {
    var a2_1: f32;
    var b2_: f32;
    var local_7: f32;

    let _e147 = (*a_2);
    let _e148 = (*a_2);
    a2_1 = (_e147 * _e148);
    let _e150 = (*b_1);
    let _e151 = (*b_1);
    b2_ = (_e150 * _e151);
    let _e153 = a2_1;
    let _e154 = b2_;
    if ((_e153 + _e154) > 0f) {
        let _e157 = a2_1;
        let _e158 = a2_1;
        let _e159 = b2_;
        local_7 = (_e157 / (_e158 + _e159));
    } else {
        local_7 = 0f;
    }
    let _e162 = local_7;
    return _e162;
}

fn mxc_env_uv_u0028_vf3_u003b(d_1: ptr<function, vec3<f32>>) -> vec2<f32> {
    var u_1: f32;
    var local_8: f32;
    var v_3: f32;

    let _e147 = (*d_1)[0u];
    let _e150 = (*d_1)[2u];
    if ((abs(_e147) + abs(_e150)) > 0.000000000001f) {
        let _e155 = (*d_1)[0u];
        let _e157 = (*d_1)[2u];
        local_8 = (0.5f + (atan2(_e155, -(_e157)) * 0.15915494f));
    } else {
        local_8 = 0.5f;
    }
    let _e162 = local_8;
    u_1 = _e162;
    let _e163 = (*d_1);
    let _e167 = (*d_1)[1u];
    v_3 = (atan2(length(_e163.xz), _e167) * 0.31830987f);
    let _e170 = u_1;
    let _e171 = v_3;
    return vec2<f32>(_e170, _e171);
}

fn mxc_env_cell_u0028_vf3_u003b(d_2: ptr<function, vec3<f32>>) -> u32 {
    var uv: vec2<f32>;
    var param_63: vec3<f32>;
    var size_1: vec2<u32>;
    var i_3: u32;
    var j_1: u32;

    let _e148 = (*d_2);
    param_63 = _e148;
    let _e149 = mxc_env_uv_u0028_vf3_u003b((&param_63));
    uv = _e149;
    let _e151 = unnamed.mxc_env_size;
    size_1 = max(_e151.xy, vec2<u32>(1u, 1u));
    let _e155 = uv[0u];
    let _e158 = size_1[0u];
    let _e163 = size_1[0u];
    i_3 = min(u32((max(_e155, 0f) * f32(_e158))), (_e163 - 1u));
    let _e167 = uv[1u];
    let _e170 = size_1[1u];
    let _e175 = size_1[1u];
    j_1 = min(u32((max(_e167, 0f) * f32(_e170))), (_e175 - 1u));
    let _e178 = j_1;
    let _e180 = size_1[0u];
    let _e182 = i_3;
    return ((_e178 * _e180) + _e182);
}

fn mxc_env_pdf_u0028_vf3_u003b(d_3: ptr<function, vec3<f32>>) -> f32 {
    var param_64: vec3<f32>;

    let _e144 = (*d_3);
    param_64 = _e144;
    let _e145 = mxc_env_cell_u0028_vf3_u003b((&param_64));
    let _e149 = unnamed.mxc_env_cells[_e145][2u];
    return _e149;
}

fn mxc_env_to_map_u0028_vf3_u003b_f1_u003b(w: ptr<function, vec3<f32>>, angle_1: ptr<function, f32>) -> vec3<f32> {
    var c_4: f32;
    var s_4: f32;

    let _e146 = (*angle_1);
    c_4 = cos(_e146);
    let _e148 = (*angle_1);
    s_4 = sin(_e148);
    let _e150 = c_4;
    let _e152 = (*w)[0u];
    let _e154 = s_4;
    let _e156 = (*w)[2u];
    let _e160 = (*w)[1u];
    let _e161 = s_4;
    let _e163 = (*w)[0u];
    let _e165 = c_4;
    let _e167 = (*w)[2u];
    return vec3<f32>(((_e150 * _e152) - (_e154 * _e156)), _e160, ((_e161 * _e163) + (_e165 * _e167)));
}

fn mxc_env_lookup_u0028_vf3_u003b(d_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_65: vec3<f32>;

    let _e144 = (*d_4);
    param_65 = _e144;
    let _e145 = mxc_env_uv_u0028_vf3_u003b((&param_65));
    let _e146 = textureSampleLevel(mxc_env_radiance_texture, mxc_env_radiance_sampler, _e145, 0f);
    return _e146.xyz;
}

fn mxc_sky_u0028_vf3_u003b(d_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var y_1: f32;
    var horizon: vec3<f32>;
    var zenith: vec3<f32>;
    var ground: vec3<f32>;

    let _e148 = (*d_5)[1u];
    y_1 = clamp(_e148, -1f, 1f);
    horizon = vec3<f32>(1f, 0.96f, 0.9f);
    zenith = vec3<f32>(0.3f, 0.5f, 0.95f);
    ground = vec3<f32>(0.16f, 0.145f, 0.13f);
    let _e150 = y_1;
    if (_e150 >= 0f) {
        let _e152 = horizon;
        let _e153 = zenith;
        let _e154 = y_1;
        return mix(_e152, _e153, vec3(sqrt(_e154)));
    }
    let _e158 = horizon;
    let _e159 = ground;
    let _e160 = y_1;
    return mix(_e158, _e159, vec3(sqrt(-(_e160))));
}

fn mxc_environment_code_u0028_() -> i32 {
    var local_9: i32;

    if false {
        local_9 = MXC_ENVIRONMENT;
    } else {
        let _e145 = mxc_view.counts[1u];
        local_9 = _e145;
    }
    let _e146 = local_9;
    return _e146;
}

fn mxc_environment_u0028_vf3_u003b(d_6: ptr<function, vec3<f32>>) -> vec3<f32> {
    var code: i32;
    var param_66: vec3<f32>;
    var param_67: vec3<f32>;
    var param_68: f32;
    var param_69: vec3<f32>;

    let _e148 = mxc_environment_code_u0028_();
    code = _e148;
    let _e149 = code;
    if (_e149 == 1i) {
        let _e153 = mxc_view.environment[0u];
        return vec3(_e153);
    }
    let _e155 = code;
    if (_e155 == 2i) {
        let _e159 = mxc_view.environment[0u];
        let _e160 = (*d_6);
        param_66 = _e160;
        let _e161 = mxc_sky_u0028_vf3_u003b((&param_66));
        return (_e161 * _e159);
    }
    let _e163 = code;
    if (_e163 == 3i) {
        let _e167 = mxc_view.environment[0u];
        let _e168 = (*d_6);
        param_67 = _e168;
        let _e171 = mxc_view.environment[2u];
        param_68 = _e171;
        let _e172 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_67), (&param_68));
        param_69 = _e172;
        let _e173 = mxc_env_lookup_u0028_vf3_u003b((&param_69));
        return (_e173 * _e167);
    }
    return vec3<f32>(0f, 0f, 0f);
}

fn mxc_exit_direction_u0028_vf3_u003b_vf3_u003b(d_7: ptr<function, vec3<f32>>, t_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var axis: vec3<f32>;
    var s_5: f32;
    var c_5: f32;

    let _e147 = (*d_7);
    let _e148 = (*t_2);
    axis = cross(_e147, _e148);
    let _e150 = axis;
    s_5 = length(_e150);
    let _e152 = s_5;
    if (_e152 < 0.000001f) {
        let _e154 = (*t_2);
        return _e154;
    }
    let _e155 = s_5;
    let _e156 = axis;
    axis = (_e156 / vec3(_e155));
    let _e159 = (*d_7);
    let _e160 = (*t_2);
    c_5 = dot(_e159, _e160);
    let _e162 = (*t_2);
    let _e163 = c_5;
    let _e165 = axis;
    let _e166 = (*t_2);
    let _e168 = s_5;
    let _e171 = axis;
    let _e172 = axis;
    let _e173 = (*t_2);
    let _e176 = c_5;
    return (((_e162 * _e163) + (cross(_e165, _e166) * _e168)) + ((_e171 * dot(_e172, _e173)) * (1f - _e176)));
}

fn mxc_to_world_u0028_mf33_u003b_vf3_u003b(frame_2: ptr<function, mat3x3<f32>>, v_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e145 = (*frame_2)[0];
    let _e147 = (*v_4)[0u];
    let _e150 = (*frame_2)[1];
    let _e152 = (*v_4)[1u];
    let _e156 = (*frame_2)[2];
    let _e158 = (*v_4)[2u];
    return (((_e145 * _e147) + (_e150 * _e152)) + (_e156 * _e158));
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

    let _e159 = (*alpha_7);
    param_70 = _e159;
    let _e160 = mxc_rough_alpha_u0028_vf2_u003b((&param_70));
    (*alpha_7) = _e160;
    let _e162 = (*alpha_7)[0u];
    let _e164 = (*wo_7)[0u];
    let _e167 = (*alpha_7)[1u];
    let _e169 = (*wo_7)[1u];
    let _e172 = (*wo_7)[2u];
    vh = normalize(vec3<f32>((_e162 * _e164), (_e167 * _e169), _e172));
    let _e176 = vh[0u];
    let _e178 = vh[0u];
    let _e181 = vh[1u];
    let _e183 = vh[1u];
    lensq = ((_e176 * _e178) + (_e181 * _e183));
    let _e186 = lensq;
    if (_e186 > 0f) {
        let _e189 = vh[1u];
        let _e192 = vh[0u];
        let _e194 = lensq;
        local_10 = (vec3<f32>(-(_e189), _e192, 0f) * inverseSqrt(_e194));
    } else {
        local_10 = vec3<f32>(1f, 0f, 0f);
    }
    let _e197 = local_10;
    t1_ = _e197;
    let _e198 = vh;
    let _e199 = t1_;
    t2_ = cross(_e198, _e199);
    let _e202 = (*u_2)[0u];
    r_1 = sqrt(_e202);
    let _e205 = (*u_2)[1u];
    phi_1 = (6.2831855f * _e205);
    let _e207 = r_1;
    let _e208 = phi_1;
    p1_ = (_e207 * cos(_e208));
    let _e211 = r_1;
    let _e212 = phi_1;
    p2_ = (_e211 * sin(_e212));
    let _e216 = vh[2u];
    s_6 = (0.5f * (1f + _e216));
    let _e219 = s_6;
    let _e221 = p1_;
    let _e222 = p1_;
    param_71 = (1f - (_e221 * _e222));
    let _e225 = mxc_safe_sqrt_u0028_f1_u003b((&param_71));
    let _e227 = s_6;
    let _e228 = p2_;
    p2_ = (((1f - _e219) * _e225) + (_e227 * _e228));
    let _e231 = p1_;
    let _e232 = t1_;
    let _e234 = p2_;
    let _e235 = t2_;
    let _e238 = p1_;
    let _e239 = p1_;
    let _e242 = p2_;
    let _e243 = p2_;
    param_72 = ((1f - (_e238 * _e239)) - (_e242 * _e243));
    let _e246 = mxc_safe_sqrt_u0028_f1_u003b((&param_72));
    let _e247 = vh;
    nh = (((_e232 * _e231) + (_e235 * _e234)) + (_e247 * _e246));
    let _e251 = (*alpha_7)[0u];
    let _e253 = nh[0u];
    let _e256 = (*alpha_7)[1u];
    let _e258 = nh[1u];
    let _e261 = nh[2u];
    return normalize(vec3<f32>((_e251 * _e253), (_e256 * _e258), max(_e261, 0f)));
}

fn mxc_sample_cosine_u0028_vf2_u003b(u_3: ptr<function, vec2<f32>>) -> vec3<f32> {
    var r_2: f32;
    var phi_2: f32;
    var param_73: f32;

    let _e147 = (*u_3)[0u];
    r_2 = sqrt(_e147);
    let _e150 = (*u_3)[1u];
    phi_2 = (6.2831855f * _e150);
    let _e152 = r_2;
    let _e153 = phi_2;
    let _e156 = r_2;
    let _e157 = phi_2;
    let _e161 = (*u_3)[0u];
    param_73 = (1f - _e161);
    let _e163 = mxc_safe_sqrt_u0028_f1_u003b((&param_73));
    return vec3<f32>((_e152 * cos(_e153)), (_e156 * sin(_e157)), _e163);
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
    var phi_2724_: bool;
    var phi_2729_: bool;
    var phi_2740_: bool;

    s_7.valid = false;
    s_7.delta = false;
    s_7.pdf = 0f;
    s_7.value = vec3<f32>(0f, 0f, 0f);
    s_7.wi = vec3<f32>(0f, 0f, 1f);
    let _e193 = (*l_8).kind;
    switch _e193 {
        case 2, 3, 1: {
            let _e220 = (*wo_8)[2u];
            above_3 = (_e220 > 0f);
            let _e222 = above_3;
            if _e222 {
                let _e223 = (*wo_8);
                local_11 = _e223;
            } else {
                let _e224 = (*wo_8);
                local_11 = -(_e224);
            }
            let _e226 = local_11;
            o_2 = _e226;
            let _e228 = o_2[2u];
            if (_e228 <= 0f) {
                let _e230 = s_7;
                return _e230;
            }
            let _e232 = (*l_8).alpha;
            param_74 = _e232;
            let _e233 = mxc_is_delta_u0028_vf2_u003b((&param_74));
            delta = _e233;
            let _e234 = delta;
            if _e234 {
                local_12 = vec3<f32>(0f, 0f, 1f);
            } else {
                let _e235 = o_2;
                param_75 = _e235;
                let _e237 = (*l_8).alpha;
                param_76 = _e237;
                let _e238 = (*u_4);
                param_77 = _e238.xy;
                let _e240 = mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b((&param_75), (&param_76), (&param_77));
                local_12 = _e240;
            }
            let _e241 = local_12;
            m_4 = _e241;
            let _e242 = o_2;
            let _e243 = m_4;
            hm = dot(_e242, _e243);
            let _e246 = (*l_8).kind;
            let _e247 = (_e246 == 1i);
            phi_2724_ = _e247;
            if !(_e247) {
                let _e250 = (*l_8).kind;
                phi_2724_ = (_e250 == 3i);
            }
            let _e253 = phi_2724_;
            phi_2729_ = _e253;
            if _e253 {
                let _e254 = (*l_8);
                param_78 = _e254;
                let _e255 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_78));
                phi_2729_ = _e255;
            }
            let _e257 = phi_2729_;
            transmits = _e257;
            let _e259 = (*l_8).kind;
            let _e260 = (_e259 == 2i);
            phi_2740_ = _e260;
            if !(_e260) {
                let _e263 = (*l_8).mode;
                phi_2740_ = ((_e263 & 1i) != 0i);
            }
            let _e267 = phi_2740_;
            reflects = _e267;
            let _e268 = hm;
            let _e270 = (*l_8);
            param_79 = _e270;
            param_80 = max(_e268, 0f);
            let _e271 = above_3;
            param_81 = _e271;
            let _e272 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_79), (&param_80), (&param_81));
            f_3 = _e272;
            let _e273 = transmits;
            if _e273 {
                let _e274 = f_3;
                param_82 = _e274;
                let _e275 = mxc_mean_u0028_vf3_u003b((&param_82));
                local_13 = _e275;
            } else {
                local_13 = 1f;
            }
            let _e276 = local_13;
            fr_1 = _e276;
            let _e277 = transmits;
            if _e277 {
                let _e278 = reflects;
                let _e279 = fr_1;
                local_14 = select(0f, _e279, _e278);
            } else {
                local_14 = 1f;
            }
            let _e281 = local_14;
            pReflect = _e281;
            let _e283 = (*u_4)[2u];
            let _e284 = pReflect;
            if (_e283 < _e284) {
                let _e286 = o_2;
                let _e288 = m_4;
                i_4 = reflect(-(_e286), _e288);
                let _e291 = i_4[2u];
                if (_e291 <= 0f) {
                    let _e293 = s_7;
                    return _e293;
                }
                let _e294 = above_3;
                if _e294 {
                    let _e295 = i_4;
                    local_15 = _e295;
                } else {
                    let _e296 = i_4;
                    local_15 = -(_e296);
                }
                let _e298 = local_15;
                s_7.wi = _e298;
                let _e300 = delta;
                s_7.delta = _e300;
                let _e302 = delta;
                if _e302 {
                    let _e304 = (*l_8).kind;
                    if (_e304 == 1i) {
                        let _e306 = above_3;
                        if _e306 {
                            let _e308 = (*l_8).c0_;
                            local_17 = _e308;
                        } else {
                            local_17 = vec3<f32>(1f, 1f, 1f);
                        }
                        let _e309 = local_17;
                        local_16 = _e309;
                    } else {
                        local_16 = vec3<f32>(1f, 1f, 1f);
                    }
                    let _e310 = local_16;
                    tint = _e310;
                    let _e311 = f_3;
                    let _e312 = tint;
                    s_7.value = (_e311 * _e312);
                    let _e315 = pReflect;
                    s_7.pdf = _e315;
                } else {
                    let _e317 = (*l_8);
                    param_83 = _e317;
                    let _e318 = (*wo_8);
                    param_84 = _e318;
                    let _e320 = s_7.wi;
                    param_85 = _e320;
                    let _e321 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_83), (&param_84), (&param_85));
                    s_7.value = _e321;
                    let _e323 = (*l_8);
                    param_86 = _e323;
                    let _e324 = (*wo_8);
                    param_87 = _e324;
                    let _e326 = s_7.wi;
                    param_88 = _e326;
                    let _e327 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_86), (&param_87), (&param_88));
                    s_7.pdf = _e327;
                }
                let _e330 = s_7.pdf;
                s_7.valid = (_e330 > 0f);
                let _e333 = s_7;
                return _e333;
            }
            let _e334 = s_7;
            return _e334;
        }
        default: {
            let _e195 = (*wo_8)[2u];
            if (_e195 <= 0f) {
                let _e197 = s_7;
                return _e197;
            }
            let _e198 = (*u_4);
            param_89 = _e198.xy;
            let _e200 = mxc_sample_cosine_u0028_vf2_u003b((&param_89));
            s_7.wi = _e200;
            let _e202 = (*l_8);
            param_90 = _e202;
            let _e203 = (*wo_8);
            param_91 = _e203;
            let _e205 = s_7.wi;
            param_92 = _e205;
            let _e206 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_90), (&param_91), (&param_92));
            s_7.value = _e206;
            let _e208 = (*l_8);
            param_93 = _e208;
            let _e209 = (*wo_8);
            param_94 = _e209;
            let _e211 = s_7.wi;
            param_95 = _e211;
            let _e212 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_93), (&param_94), (&param_95));
            s_7.pdf = _e212;
            let _e215 = s_7.pdf;
            s_7.valid = (_e215 > 0f);
            let _e218 = s_7;
            return _e218;
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
    let _e176 = (*wo_9);
    s_8.wi = _e176;
    let _e179 = (*c_6).choiceTotal;
    total = _e179;
    let _e181 = (*c_6).count;
    let _e183 = total;
    if ((_e181 == 0i) || (_e183 <= 0f)) {
        let _e186 = s_8;
        return _e186;
    }
    let _e188 = (*u_5)[2u];
    let _e189 = total;
    x_2 = (_e188 * _e189);
    chosen = -1i;
    before = 0f;
    p_2 = 0f;
    lastBefore = 0f;
    last = -1i;
    k_2 = 0i;
    loop {
        let _e191 = k_2;
        let _e193 = (*c_6).count;
        if (_e191 < _e193) {
            let _e195 = k_2;
            let _e198 = (*c_6).choice[_e195];
            pk = _e198;
            let _e199 = pk;
            if (_e199 <= 0f) {
                continue;
            }
            let _e201 = x_2;
            let _e202 = before;
            let _e203 = pk;
            if (_e201 < (_e202 + _e203)) {
                let _e206 = k_2;
                chosen = _e206;
                let _e207 = pk;
                p_2 = _e207;
                break;
            }
            let _e208 = k_2;
            last = _e208;
            let _e209 = before;
            lastBefore = _e209;
            let _e210 = pk;
            let _e211 = before;
            before = (_e211 + _e210);
            continue;
        } else {
            break;
        }
        continuing {
            let _e213 = k_2;
            k_2 = (_e213 + 1i);
        }
    }
    let _e215 = chosen;
    if (_e215 < 0i) {
        let _e217 = last;
        chosen = max(_e217, 0i);
        let _e219 = chosen;
        let _e222 = (*c_6).choice[_e219];
        p_2 = _e222;
        let _e223 = lastBefore;
        before = _e223;
    }
    let _e224 = p_2;
    if (_e224 <= 0f) {
        let _e226 = s_8;
        return _e226;
    }
    let _e227 = x_2;
    let _e228 = before;
    let _e230 = p_2;
    uz = clamp(((_e227 - _e228) / _e230), 0f, 0.99999994f);
    let _e233 = chosen;
    let _e236 = (*c_6).lobes[_e233];
    l_9 = _e236;
    let _e238 = l_9.N;
    param_96 = _e238;
    let _e240 = l_9.T;
    param_97 = _e240;
    let _e241 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_96), (&param_97));
    frame_3 = _e241;
    let _e242 = frame_3;
    param_98 = _e242;
    let _e243 = (*wo_9);
    param_99 = _e243;
    let _e244 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_98), (&param_99));
    o_3 = _e244;
    let _e245 = (*u_5);
    let _e246 = _e245.xy;
    let _e247 = uz;
    let _e251 = l_9;
    param_100 = _e251;
    let _e252 = o_3;
    param_101 = _e252;
    param_102 = vec3<f32>(_e246.x, _e246.y, _e247);
    let _e253 = mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_100), (&param_101), (&param_102));
    ls = _e253;
    let _e255 = ls.valid;
    if !(_e255) {
        let _e257 = s_8;
        return _e257;
    }
    let _e258 = frame_3;
    param_103 = _e258;
    let _e260 = ls.wi;
    param_104 = _e260;
    let _e261 = mxc_to_world_u0028_mf33_u003b_vf3_u003b((&param_103), (&param_104));
    s_8.wi = _e261;
    let _e264 = ls.delta;
    if _e264 {
        s_8.delta = true;
        let _e267 = ls.pdf;
        let _e268 = p_2;
        let _e270 = total;
        s_8.pdf = ((_e267 * _e268) / _e270);
        let _e274 = l_9.weight;
        let _e275 = chosen;
        let _e278 = (*c_6).ms[_e275];
        let _e282 = ls.wi[2u];
        let _e284 = l_9;
        param_105 = _e284;
        param_106 = abs(_e282);
        let _e285 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_105), (&param_106));
        let _e288 = ls.value;
        let _e291 = s_8.pdf;
        s_8.weight = ((((_e274 * _e278) * _e285) * _e288) / vec3(_e291));
        let _e296 = s_8.pdf;
        s_8.valid = (_e296 > 0f);
        let _e299 = s_8;
        return _e299;
    }
    s_8.evaluate = true;
    s_8.valid = true;
    let _e302 = s_8;
    return _e302;
}

fn mxc_radical_inverse_u0028_u1_u003b_u1_u003b(i_5: ptr<function, u32>, base: ptr<function, u32>) -> f32 {
    var inv: f32;
    var f_4: f32;
    var r_3: f32;

    let _e147 = (*base);
    if (_e147 == 2u) {
        let _e149 = (*i_5);
        return (f32((reverseBits(_e149) >> bitcast<u32>(8i))) * 0.000000059604645f);
    }
    let _e155 = (*base);
    inv = (1f / f32(_e155));
    let _e158 = inv;
    f_4 = _e158;
    r_3 = 0f;
    loop {
        let _e159 = (*i_5);
        if (_e159 > 0u) {
            let _e161 = f_4;
            let _e162 = (*i_5);
            let _e163 = (*base);
            let _e167 = r_3;
            r_3 = (_e167 + (_e161 * f32((_e162 % _e163))));
            let _e169 = inv;
            let _e170 = f_4;
            f_4 = (_e170 * _e169);
            continue;
        } else {
            break;
        }
        continuing {
            let _e172 = (*base);
            let _e173 = (*i_5);
            (*i_5) = (_e173 / _e172);
        }
    }
    let _e175 = r_3;
    return min(_e175, 0.99999994f);
}

fn mxc_pcg_u0028_u1_u003b(v_5: ptr<function, u32>) -> u32 {
    var state: u32;
    var word: u32;

    let _e145 = (*v_5);
    state = ((_e145 * 747796405u) + 2891336453u);
    let _e148 = state;
    let _e149 = state;
    let _e155 = state;
    word = (((_e148 >> bitcast<u32>(((_e149 >> bitcast<u32>(28u)) + 4u))) ^ _e155) * 277803737u);
    let _e158 = word;
    let _e161 = word;
    return ((_e158 >> bitcast<u32>(22u)) ^ _e161);
}

fn mxc_uniform_u0028_u1_u003b(seed: ptr<function, u32>) -> f32 {
    var param_107: u32;

    let _e144 = (*seed);
    param_107 = _e144;
    let _e145 = mxc_pcg_u0028_u1_u003b((&param_107));
    (*seed) = _e145;
    let _e146 = (*seed);
    return (f32((_e146 >> bitcast<u32>(8i))) * 0.000000059604645f);
}

fn mxc_light_kinds_u0028_() -> i32 {
    return 7i;
}

fn mxc_light_count_u0028_() -> i32 {
    var local_18: i32;

    if false {
        local_18 = MXC_LIGHT_COUNT;
    } else {
        let _e145 = mxc_view.counts[0u];
        local_18 = _e145;
    }
    let _e146 = local_18;
    return min(_e146, 8i);
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

    let _e152 = (*sigma_1);
    a_3 = (1f / (1f + (0.2877934f * _e152)));
    let _e156 = (*mu_1);
    c_7 = clamp(_e156, 0f, 1f);
    let _e158 = c_7;
    let _e159 = c_7;
    param_108 = (1f - (_e158 * _e159));
    let _e162 = mxc_safe_sqrt_u0028_f1_u003b((&param_108));
    s_9 = _e162;
    let _e163 = c_7;
    theta = acos(_e163);
    let _e165 = c_7;
    if (_e165 > 0.0001f) {
        let _e167 = s_9;
        let _e168 = s_9;
        let _e170 = s_9;
        let _e173 = c_7;
        local_19 = ((1f - ((_e167 * _e168) * _e170)) / _e173);
    } else {
        let _e175 = c_7;
        local_19 = (1.5f * _e175);
    }
    let _e177 = local_19;
    tail = _e177;
    let _e178 = s_9;
    let _e179 = theta;
    let _e180 = s_9;
    let _e181 = c_7;
    let _e185 = s_9;
    let _e187 = tail;
    let _e190 = s_9;
    g = (((_e178 * (_e179 - (_e180 * _e181))) + ((0.6666667f * _e185) * _e187)) - (0.6666667f * _e190));
    let _e193 = a_3;
    let _e194 = (*sigma_1);
    let _e195 = a_3;
    let _e197 = g;
    return (_e193 + (((_e194 * _e195) * _e197) * 0.31830987f));
}

fn mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b(mu_2: ptr<function, f32>, x_3: ptr<function, f32>, firstRow: ptr<function, f32>) -> vec4<f32> {
    var t_3: vec2<f32>;

    let _e146 = (*mu_2);
    let _e149 = (*x_3);
    t_3 = ((vec2<f32>(sqrt(clamp(_e146, 0f, 1f)), clamp(_e149, 0f, 1f)) * 31f) + vec2(0.5f));
    let _e156 = t_3[0u];
    let _e158 = (*firstRow);
    let _e160 = t_3[1u];
    let _e164 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, vec2<f32>((_e156 / 32f), ((_e158 + _e160) / 1654f)), 0f);
    return _e164;
}

fn mxc_table_u0028_f1_u003b_f1_u003b(mu_3: ptr<function, f32>, x_4: ptr<function, f32>) -> vec4<f32> {
    var param_109: f32;
    var param_110: f32;
    var param_111: f32;

    let _e147 = (*mu_3);
    param_109 = _e147;
    let _e148 = (*x_4);
    param_110 = _e148;
    param_111 = 0f;
    let _e149 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_109), (&param_110), (&param_111));
    return _e149;
}

fn mxc_split_sum_u0028_f1_u003b_f1_u003b(mu_4: ptr<function, f32>, alpha_8: ptr<function, f32>) -> vec2<f32> {
    var param_112: f32;
    var param_113: f32;

    let _e146 = (*alpha_8);
    let _e149 = (*mu_4);
    param_112 = _e149;
    param_113 = sqrt(max(_e146, 0f));
    let _e150 = mxc_table_u0028_f1_u003b_f1_u003b((&param_112), (&param_113));
    return _e150.xy;
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

    let _e156 = (*e);
    s_10 = (sqrt(clamp((0.5f * (_e156 - 1f)), 0f, 1f)) * 31f);
    let _e162 = s_10;
    s0_ = min(floor(_e162), 30f);
    let _e165 = (*alpha_9);
    x_5 = sqrt(max(_e165, 0f));
    let _e168 = s0_;
    let _e171 = (*mu_5);
    param_114 = _e171;
    let _e172 = x_5;
    param_115 = _e172;
    param_116 = (32f * (1f + _e168));
    let _e173 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_114), (&param_115), (&param_116));
    a_4 = _e173;
    let _e174 = s0_;
    let _e177 = (*mu_5);
    param_117 = _e177;
    let _e178 = x_5;
    param_118 = _e178;
    param_119 = (32f * (2f + _e174));
    let _e179 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_117), (&param_118), (&param_119));
    b_2 = _e179;
    let _e180 = a_4;
    let _e181 = b_2;
    let _e182 = s_10;
    let _e183 = s0_;
    return mix(_e180, _e181, vec4((_e182 - _e183)));
}

fn mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b(mu_6: ptr<function, f32>, alpha_10: ptr<function, f32>, eta_1: ptr<function, f32>) -> f32 {
    var e_1: f32;
    var local_20: f32;
    var param_120: f32;
    var param_121: f32;
    var param_122: f32;

    let _e150 = (*eta_1);
    if (_e150 >= 1f) {
        let _e152 = (*eta_1);
        local_20 = _e152;
    } else {
        let _e153 = (*eta_1);
        local_20 = (1f / max(_e153, 0.001f));
    }
    let _e156 = local_20;
    e_1 = _e156;
    let _e157 = (*mu_6);
    param_120 = _e157;
    let _e158 = (*alpha_10);
    param_121 = _e158;
    let _e159 = e_1;
    param_122 = _e159;
    let _e160 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_120), (&param_121), (&param_122));
    return _e160.x;
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
    var phi_2225_: bool;
    var phi_2232_: bool;
    var phi_2250_: bool;

    let _e172 = (*wo_10)[2u];
    mu_7 = clamp(_e172, 0f, 1f);
    let _e175 = (*l_10).kind;
    let _e176 = (_e175 == 1i);
    phi_2225_ = _e176;
    if !(_e176) {
        let _e179 = (*l_10).kind;
        phi_2225_ = (_e179 == 2i);
    }
    let _e182 = phi_2225_;
    phi_2232_ = _e182;
    if !(_e182) {
        let _e185 = (*l_10).kind;
        phi_2232_ = (_e185 == 3i);
    }
    let _e188 = phi_2232_;
    if _e188 {
        let _e191 = (*l_10).alpha[0u];
        let _e194 = (*l_10).alpha[1u];
        alpha_11 = sqrt((_e191 * _e194));
        let _e198 = (*l_10).kind;
        let _e199 = (_e198 == 1i);
        phi_2250_ = _e199;
        if _e199 {
            let _e201 = (*l_10).alpha;
            param_123 = _e201;
            let _e202 = mxc_is_delta_u0028_vf2_u003b((&param_123));
            phi_2250_ = !(_e202);
        }
        let _e205 = phi_2250_;
        if _e205 {
            let _e206 = mu_7;
            param_124 = _e206;
            let _e207 = alpha_11;
            param_125 = _e207;
            let _e209 = (*l_10).eta;
            param_126 = _e209;
            let _e210 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_124), (&param_125), (&param_126));
            e_2 = vec3(_e210);
            let _e212 = e_2;
            let _e214 = (*l_10).c0_;
            let _e216 = (*ms);
            return clamp(((_e212 * _e214) * _e216), vec3(0f), vec3(1f));
        }
        let _e221 = mu_7;
        param_127 = _e221;
        let _e222 = alpha_11;
        param_128 = _e222;
        let _e223 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_127), (&param_128));
        ab = _e223;
        let _e224 = (*l_10);
        param_129 = _e224;
        param_130 = 1f;
        param_131 = true;
        let _e225 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_129), (&param_130), (&param_131));
        f0_ = _e225;
        let _e226 = (*l_10);
        param_132 = _e226;
        param_133 = 0f;
        param_134 = true;
        let _e227 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_132), (&param_133), (&param_134));
        f90_ = _e227;
        let _e229 = (*l_10).kind;
        if (_e229 == 1i) {
            let _e232 = (*l_10).c0_;
            local_21 = _e232;
        } else {
            local_21 = vec3<f32>(1f, 1f, 1f);
        }
        let _e233 = local_21;
        tint_1 = _e233;
        let _e235 = (*l_10).alpha;
        param_135 = _e235;
        let _e236 = mxc_is_delta_u0028_vf2_u003b((&param_135));
        if _e236 {
            let _e237 = (*l_10);
            param_136 = _e237;
            let _e238 = mu_7;
            param_137 = _e238;
            param_138 = true;
            let _e239 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_136), (&param_137), (&param_138));
            let _e240 = tint_1;
            return (_e239 * _e240);
        }
        let _e242 = f0_;
        let _e244 = ab[0u];
        let _e246 = f90_;
        let _e248 = ab[1u];
        let _e251 = tint_1;
        let _e253 = (*ms);
        return clamp(((((_e242 * _e244) + (_e246 * _e248)) * _e251) * _e253), vec3(0f), vec3(1f));
    }
    let _e259 = (*l_10).kind;
    if (_e259 == 4i) {
        let _e262 = (*l_10).c0_;
        let _e264 = (*l_10).p0_;
        param_139 = _e264;
        let _e265 = mu_7;
        param_140 = _e265;
        let _e266 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_139), (&param_140));
        return (_e262 * _e266);
    }
    let _e269 = (*l_10).kind;
    if (_e269 == 8i) {
        let _e272 = (*l_10).c0_;
        return _e272;
    }
    let _e274 = (*l_10).c0_;
    return _e274;
}

fn mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_11: ptr<function, MxcLobe>, woLocal: ptr<function, vec3<f32>>, ms_1: ptr<function, vec3<f32>>) -> f32 {
    var param_141: MxcLobe;
    var param_142: vec3<f32>;
    var param_143: vec3<f32>;
    var param_144: vec3<f32>;

    let _e150 = (*l_11).weight;
    if all((_e150 == vec3<f32>(0f, 0f, 0f))) {
        return 0f;
    }
    let _e154 = (*l_11).weight;
    let _e155 = (*l_11);
    param_141 = _e155;
    let _e156 = (*woLocal);
    param_142 = _e156;
    let _e157 = (*ms_1);
    param_143 = _e157;
    let _e158 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_141), (&param_142), (&param_143));
    param_144 = (_e154 * _e158);
    let _e160 = mxc_luminance_u0028_vf3_u003b((&param_144));
    return (max(_e160, 0f) + 0.0001f);
}

fn mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b(mu_8: ptr<function, f32>, alpha_12: ptr<function, f32>, eta_2: ptr<function, f32>) -> f32 {
    var param_145: f32;
    var param_146: f32;
    var param_147: f32;
    var param_148: f32;
    var param_149: f32;
    var param_150: f32;

    let _e151 = (*eta_2);
    if (_e151 >= 1f) {
        let _e153 = (*mu_8);
        param_145 = _e153;
        let _e154 = (*alpha_12);
        param_146 = _e154;
        let _e155 = (*eta_2);
        param_147 = _e155;
        let _e156 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_145), (&param_146), (&param_147));
        return _e156.y;
    }
    let _e158 = (*eta_2);
    let _e161 = (*mu_8);
    param_148 = _e161;
    let _e162 = (*alpha_12);
    param_149 = _e162;
    param_150 = (1f / max(_e158, 0.001f));
    let _e163 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_148), (&param_149), (&param_150));
    return _e163.z;
}

fn mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_12: ptr<function, MxcLobe>) -> bool {
    let _e144 = (*l_12).eta;
    return (abs((_e144 - 1f)) < 0.0001f);
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
    var phi_2099_: bool;
    var phi_2106_: bool;
    var phi_2115_: bool;
    var phi_2131_: bool;
    var phi_2143_: bool;

    let _e163 = (*l_13).kind;
    let _e164 = (_e163 == 1i);
    phi_2099_ = _e164;
    if !(_e164) {
        let _e167 = (*l_13).kind;
        phi_2099_ = (_e167 == 2i);
    }
    let _e170 = phi_2099_;
    phi_2106_ = _e170;
    if !(_e170) {
        let _e173 = (*l_13).kind;
        phi_2106_ = (_e173 == 3i);
    }
    let _e176 = phi_2106_;
    microfacet = _e176;
    let _e177 = microfacet;
    let _e178 = !(_e177);
    phi_2115_ = _e178;
    if !(_e178) {
        let _e181 = (*l_13).alpha;
        param_151 = _e181;
        let _e182 = mxc_is_delta_u0028_vf2_u003b((&param_151));
        phi_2115_ = _e182;
    }
    let _e184 = phi_2115_;
    if _e184 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e187 = (*l_13).alpha[0u];
    let _e190 = (*l_13).alpha[1u];
    alpha_13 = sqrt((_e187 * _e190));
    let _e194 = (*l_13).kind;
    let _e195 = (_e194 == 1i);
    phi_2131_ = _e195;
    if _e195 {
        let _e196 = (*l_13);
        param_152 = _e196;
        let _e197 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_152));
        phi_2131_ = _e197;
    }
    let _e199 = phi_2131_;
    if _e199 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e201 = (*l_13).kind;
    let _e202 = (_e201 == 1i);
    phi_2143_ = _e202;
    if _e202 {
        let _e204 = (*l_13).mode;
        phi_2143_ = ((_e204 & 4i) == 0i);
    }
    let _e208 = phi_2143_;
    if _e208 {
        let _e210 = (*wo_11)[2u];
        let _e213 = (*wo_11)[2u];
        let _e215 = (*l_13);
        param_153 = _e215;
        param_154 = (_e213 >= 0f);
        let _e216 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_153), (&param_154));
        param_155 = abs(_e210);
        let _e217 = alpha_13;
        param_156 = _e217;
        param_157 = _e216;
        let _e218 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_155), (&param_156), (&param_157));
        e_3 = _e218;
        let _e219 = e_3;
        k_3 = vec3((1f / max(_e219, 0.05f)));
        let _e223 = k_3;
        return _e223;
    }
    let _e225 = (*wo_11)[2u];
    param_158 = max(_e225, 0f);
    let _e227 = alpha_13;
    param_159 = _e227;
    let _e228 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_158), (&param_159));
    ab_1 = _e228;
    let _e230 = ab_1[0u];
    let _e232 = ab_1[1u];
    e_4 = (_e230 + _e232);
    let _e234 = (*l_13);
    param_160 = _e234;
    param_161 = 1f;
    param_162 = true;
    let _e235 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_160), (&param_161), (&param_162));
    let _e236 = e_4;
    let _e239 = e_4;
    return (vec3(1f) + ((_e235 * (1f - _e236)) / vec3(max(_e239, 0.05f))));
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
        let _e157 = k_4;
        let _e159 = (*c_8).count;
        if (_e157 < _e159) {
            let _e161 = k_4;
            let _e164 = (*c_8).lobes[_e161];
            l_14 = _e164;
            let _e165 = k_4;
            (*c_8).ms[_e165] = vec3<f32>(1f, 1f, 1f);
            let _e168 = k_4;
            (*c_8).choice[_e168] = 0f;
            let _e172 = l_14.weight;
            if all((_e172 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e176 = l_14.N;
            param_163 = _e176;
            let _e178 = l_14.T;
            param_164 = _e178;
            let _e179 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_163), (&param_164));
            param_165 = _e179;
            let _e180 = (*wo_12);
            param_166 = _e180;
            let _e181 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_165), (&param_166));
            o_4 = _e181;
            let _e182 = k_4;
            let _e183 = l_14;
            param_167 = _e183;
            let _e184 = o_4;
            param_168 = _e184;
            let _e185 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_167), (&param_168));
            (*c_8).ms[_e182] = _e185;
            let _e188 = k_4;
            let _e189 = k_4;
            let _e190 = l_14;
            param_169 = _e190;
            let _e191 = o_4;
            param_170 = _e191;
            let _e194 = (*c_8).ms[_e189];
            param_171 = _e194;
            let _e195 = mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_169), (&param_170), (&param_171));
            (*c_8).choice[_e188] = _e195;
            let _e198 = k_4;
            let _e201 = (*c_8).choice[_e198];
            let _e203 = (*c_8).choiceTotal;
            (*c_8).choiceTotal = (_e203 + _e201);
            continue;
        } else {
            break;
        }
        continuing {
            let _e206 = k_4;
            k_4 = (_e206 + 1i);
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

    let _e149 = (*l_15);
    param_172 = _e149;
    let _e150 = (*wo_13);
    param_173 = _e150;
    let _e151 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_172), (&param_173));
    let _e152 = (*l_15);
    param_174 = _e152;
    let _e153 = (*wo_13);
    param_175 = _e153;
    param_176 = _e151;
    let _e154 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_174), (&param_175), (&param_176));
    return _e154;
}

fn mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_16: ptr<function, MxcLobe>, wo_14: ptr<function, vec3<f32>>) -> vec3<f32> {
    var white: MxcLobe;
    var param_177: MxcLobe;
    var param_178: vec3<f32>;
    var param_179: MxcLobe;
    var param_180: vec3<f32>;
    var phi_2364_: bool;

    let _e150 = (*l_16).kind;
    let _e151 = (_e150 == 9i);
    phi_2364_ = _e151;
    if !(_e151) {
        let _e154 = (*l_16).kind;
        phi_2364_ = (_e154 == 10i);
    }
    let _e157 = phi_2364_;
    if _e157 {
        let _e158 = (*l_16);
        white = _e158;
        white.c0_ = vec3<f32>(1f, 1f, 1f);
        let _e160 = white;
        param_177 = _e160;
        let _e161 = (*wo_14);
        param_178 = _e161;
        let _e162 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_177), (&param_178));
        return _e162;
    }
    let _e163 = (*l_16);
    param_179 = _e163;
    let _e164 = (*wo_14);
    param_180 = _e164;
    let _e165 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_179), (&param_180));
    return _e165;
}

fn mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b(v_6: ptr<function, vec3<f32>>, fallback: ptr<function, vec3<f32>>) -> vec3<f32> {
    var l2_1: f32;
    var local_22: vec3<f32>;

    let _e146 = (*v_6);
    let _e147 = (*v_6);
    l2_1 = dot(_e146, _e147);
    let _e149 = l2_1;
    if (_e149 > 0.00000000000000000001f) {
        let _e151 = (*v_6);
        let _e152 = l2_1;
        local_22 = (_e151 * inverseSqrt(_e152));
    } else {
        let _e155 = (*fallback);
        local_22 = _e155;
    }
    let _e156 = local_22;
    return _e156;
}

fn mxc_normalmap_u0028_vf3_u003b_vf2_u003b_vf3_u003b_vf3_u003b_vf3_u003b(sampleValue: ptr<function, vec3<f32>>, scale: ptr<function, vec2<f32>>, N_1: ptr<function, vec3<f32>>, T_1: ptr<function, vec3<f32>>, B: ptr<function, vec3<f32>>) -> vec3<f32> {
    var v_7: vec3<f32>;
    var param_181: vec3<f32>;
    var param_182: vec3<f32>;

    let _e150 = (*sampleValue);
    v_7 = ((_e150 * 2f) - vec3(1f));
    let _e154 = (*scale);
    let _e155 = v_7;
    let _e157 = (_e155.xy * _e154);
    v_7[0u] = _e157.x;
    v_7[1u] = _e157.y;
    let _e162 = (*T_1);
    let _e164 = v_7[0u];
    let _e166 = (*B);
    let _e168 = v_7[1u];
    let _e171 = (*N_1);
    let _e173 = v_7[2u];
    param_181 = (((_e162 * _e164) + (_e166 * _e168)) + (_e171 * _e173));
    let _e176 = (*N_1);
    param_182 = _e176;
    let _e177 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_181), (&param_182));
    return _e177;
}

fn mxc_hsv_to_rgb_u0028_vf3_u003b(hsv: ptr<function, vec3<f32>>) -> vec3<f32> {
    var k_5: vec3<f32>;

    let _e145 = (*hsv)[0u];
    k_5 = clamp((abs(((fract((vec3(_e145) + vec3<f32>(0f, 0.6666667f, 0.33333334f))) * 6f) - vec3(3f))) - vec3(1f)), vec3(0f), vec3(1f));
    let _e159 = (*hsv)[2u];
    let _e160 = k_5;
    let _e162 = (*hsv)[1u];
    return (mix(vec3<f32>(1f, 1f, 1f), _e160, vec3(_e162)) * _e159);
}

fn mxc_address_u0028_f1_u003b_i1_u003b(x_6: ptr<function, f32>, mode: ptr<function, i32>) -> bool {
    let _e144 = (*mode);
    if (_e144 == 0i) {
        let _e146 = (*x_6);
        let _e148 = (*x_6);
        return ((_e146 >= 0f) && (_e148 <= 1f));
    }
    let _e151 = (*mode);
    if (_e151 == 1i) {
        let _e153 = (*x_6);
        (*x_6) = clamp(_e153, 0f, 1f);
    } else {
        let _e155 = (*mode);
        if (_e155 == 2i) {
            let _e157 = (*x_6);
            (*x_6) = fract(_e157);
        } else {
            let _e159 = (*x_6);
            (*x_6) = (1f - abs(((_e159 - (floor((_e159 / 2f)) * 2f)) - 1f)));
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
    var phi_1651_: bool;

    let _e158 = (*uv_1);
    let _e159 = dpdx(_e158);
    let _e160 = mxc_texture_footprint;
    let _e161 = mxc_texture_footprint;
    dx = (_e159 * vec2<f32>(_e160, -(_e161)));
    let _e165 = (*uv_1);
    let _e166 = dpdy(_e165);
    let _e167 = mxc_texture_footprint;
    let _e168 = mxc_texture_footprint;
    dy = (_e166 * vec2<f32>(_e167, -(_e168)));
    let _e172 = (*uv_1);
    st = _e172;
    let _e173 = (*missing);
    if _e173 {
        let _e174 = (*fallback_1);
        return _e174;
    }
    let _e176 = st[0u];
    param_183 = _e176;
    let _e177 = (*uaddress);
    param_184 = _e177;
    let _e178 = mxc_address_u0028_f1_u003b_i1_u003b((&param_183), (&param_184));
    let _e179 = param_183;
    st[0u] = _e179;
    let _e181 = !(_e178);
    phi_1651_ = _e181;
    if !(_e181) {
        let _e184 = st[1u];
        param_185 = _e184;
        let _e185 = (*vaddress);
        param_186 = _e185;
        let _e186 = mxc_address_u0028_f1_u003b_i1_u003b((&param_185), (&param_186));
        let _e187 = param_185;
        st[1u] = _e187;
        phi_1651_ = !(_e186);
    }
    let _e191 = phi_1651_;
    if _e191 {
        let _e192 = (*fallback_1);
        return _e192;
    }
    let _e194 = st[1u];
    st[1u] = (1f - _e194);
    let _e197 = (*filtertype);
    if (_e197 == 1i) {
        let _e199 = textureDimensions(image_texture, 0i);
        size_2 = vec2<f32>(vec2<i32>(_e199));
        let _e202 = st;
        let _e203 = size_2;
        let _e206 = size_2;
        let _e212 = size_2;
        let _e214 = textureSampleLevel(image_texture, image_sampler, ((min(floor((_e202 * _e203)), (_e206 - vec2(1f))) + vec2(0.5f)) / _e212), 0f);
        return _e214;
    }
    let _e215 = st;
    let _e216 = dx;
    let _e217 = dy;
    let _e218 = textureSampleGrad(image_texture, image_sampler, _e215, _e216, _e217);
    return _e218;
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

    let _e238 = (*g_1).uv;
    v3_ = _e238;
    let _e239 = v3_;
    v4_ = (_e239 * vec2<f32>(3f, 3f));
    let _e242 = mxc_params.missing_textures;
    let _e245 = v4_;
    param_187 = _e245;
    param_188 = vec4<f32>(0f, 0f, 0f, 0f);
    param_189 = 2i;
    param_190 = 2i;
    param_191 = 0i;
    param_192 = ((_e242 & 1u) != 0u);
    let _e246 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_0_texture, mxc_texture_0_sampler, (&param_187), (&param_188), (&param_189), (&param_190), (&param_191), (&param_192));
    v8_ = _e246.x;
    let _e248 = v8_;
    v10_ = max(_e248, 0.00001f);
    let _e250 = v10_;
    v11_ = (0.853f / _e250);
    let _e253 = mxc_params.missing_textures;
    let _e256 = v4_;
    param_193 = _e256;
    param_194 = vec4<f32>(0f, 0f, 0f, 0f);
    param_195 = 2i;
    param_196 = 2i;
    param_197 = 0i;
    param_198 = ((_e253 & 2u) != 0u);
    let _e257 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_1_texture, mxc_texture_1_sampler, (&param_193), (&param_194), (&param_195), (&param_196), (&param_197), (&param_198));
    v13_ = _e257.x;
    let _e259 = v11_;
    let _e260 = v13_;
    v14_ = (_e259 * _e260);
    let _e263 = mxc_params.missing_textures;
    let _e266 = v4_;
    param_199 = _e266;
    param_200 = vec4<f32>(0f, 0f, 0f, 0f);
    param_201 = 2i;
    param_202 = 2i;
    param_203 = 0i;
    param_204 = ((_e263 & 4u) != 0u);
    let _e267 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_2_texture, mxc_texture_2_sampler, (&param_199), (&param_200), (&param_201), (&param_202), (&param_203), (&param_204));
    v20_ = _e267.x;
    let _e269 = v20_;
    v21_ = (0.248f * _e269);
    let _e272 = mxc_params.missing_textures;
    let _e275 = v4_;
    param_205 = _e275;
    param_206 = vec4<f32>(0f, 0f, 0f, 0f);
    param_207 = 2i;
    param_208 = 2i;
    param_209 = 0i;
    param_210 = ((_e272 & 8u) != 0u);
    let _e276 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_3_texture, mxc_texture_3_sampler, (&param_205), (&param_206), (&param_207), (&param_208), (&param_209), (&param_210));
    v25_ = _e276.x;
    let _e278 = v25_;
    v26_ = (0.083f * _e278);
    let _e281 = mxc_params.missing_textures;
    let _e284 = v4_;
    param_211 = _e284;
    param_212 = vec4<f32>(0f, 0f, 0f, 0f);
    param_213 = 2i;
    param_214 = 2i;
    param_215 = 0i;
    param_216 = ((_e281 & 16u) != 0u);
    let _e285 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_4_texture, mxc_texture_4_sampler, (&param_211), (&param_212), (&param_213), (&param_214), (&param_215), (&param_216));
    v28_ = _e285.x;
    let _e287 = v26_;
    let _e288 = v28_;
    v29_ = (_e287 + _e288);
    let _e290 = v29_;
    v31_ = (_e290 - 0.35f);
    let _e292 = v31_;
    v32_ = (_e292 * 0.083f);
    let _e294 = v25_;
    v34_ = (0.787f * _e294);
    let _e296 = v29_;
    let _e297 = v34_;
    v35_ = (_e296 * _e297);
    let _e299 = v32_;
    let _e300 = v35_;
    v36_ = vec3<f32>(_e299, 0f, _e300);
    let _e302 = v36_;
    v38_ = (_e302 + vec3<f32>(0.048065394f, 1f, 0.661876f));
    let _e304 = v38_;
    param_217 = _e304;
    let _e305 = mxc_hsv_to_rgb_u0028_vf3_u003b((&param_217));
    v39_ = _e305;
    let _e306 = v39_;
    let _e307 = v21_;
    v40_ = mix(_e306, vec3<f32>(0.56372f, 0.56372f, 0.56372f), vec3(_e307));
    let _e310 = v40_;
    let _e311 = v28_;
    v41_ = (_e310 * _e311);
    let _e313 = v28_;
    v43_ = (vec3<f32>(0.263273f, 0.263273f, 0.263273f) * _e313);
    let _e315 = v43_;
    let _e316 = v41_;
    let _e317 = v8_;
    v44_ = mix(_e315, _e316, vec3(_e317));
    let _e320 = v44_;
    v45_ = clamp(_e320, vec3<f32>(0f, 0f, 0f), vec3<f32>(1f, 1f, 1f));
    let _e322 = v45_;
    v46_ = clamp(_e322, vec3<f32>(0f, 0f, 0f), vec3<f32>(1f, 1f, 1f));
    let _e325 = mxc_params.missing_textures;
    let _e328 = v4_;
    param_218 = _e328;
    param_219 = vec4<f32>(0f, 0f, 0f, 1f);
    param_220 = 2i;
    param_221 = 2i;
    param_222 = 0i;
    param_223 = ((_e325 & 32u) != 0u);
    let _e329 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_5_texture, mxc_texture_5_sampler, (&param_218), (&param_219), (&param_220), (&param_221), (&param_222), (&param_223));
    v48_ = _e329.xyz;
    let _e332 = (*g_1).N;
    v49_ = _e332;
    let _e334 = (*g_1).T;
    v50_ = _e334;
    let _e336 = (*g_1).B;
    v51_ = _e336;
    let _e337 = v48_;
    param_224 = _e337;
    param_225 = vec2<f32>(1f, 1f);
    let _e338 = v49_;
    param_226 = _e338;
    let _e339 = v50_;
    param_227 = _e339;
    let _e340 = v51_;
    param_228 = _e340;
    let _e341 = mxc_normalmap_u0028_vf3_u003b_vf2_u003b_vf3_u003b_vf3_u003b_vf3_u003b((&param_224), (&param_225), (&param_226), (&param_227), (&param_228));
    v52_ = _e341;
    let _e342 = v14_;
    let _e343 = v14_;
    v55_ = (_e342 * _e343);
    let _e345 = v55_;
    v56_ = clamp(_e345, 0.0000001f, 1f);
    let _e347 = v56_;
    let _e348 = v56_;
    v57_ = vec2<f32>(_e347, _e348);
    (*c_9).emission = vec3<f32>(0f, 0f, 0f);
    (*c_9).transparency = vec3<f32>(0f, 0f, 0f);
    lobe0_.kind = 1i;
    lobe0_.mode = 1i;
    let _e354 = v52_;
    param_229 = _e354;
    let _e356 = (*g_1).N;
    param_230 = _e356;
    let _e357 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_229), (&param_230));
    lobe0_.N = _e357;
    let _e359 = v50_;
    lobe0_.T = _e359;
    let _e361 = v57_;
    lobe0_.alpha = _e361;
    lobe0_.eta = 1.5f;
    lobe0_.c0_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.p0_ = 0f;
    lobe0_.p1_ = 1f;
    lobe0_.film = vec3<f32>(0f, 0f, 0f);
    lobe0_.tau = vec3<f32>(0f, 0f, 0f);
    lobe0_.tauEta = 1f;
    let _e373 = lobe0_.N;
    param_231 = _e373;
    let _e375 = lobe0_.T;
    param_232 = _e375;
    let _e376 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_231), (&param_232));
    param_233 = _e376;
    let _e377 = (*wo_15);
    param_234 = _e377;
    let _e378 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_233), (&param_234));
    let _e379 = lobe0_;
    param_235 = _e379;
    param_236 = _e378;
    let _e380 = mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_235), (&param_236));
    e1_ = _e380;
    let _e381 = e1_;
    w2_ = (vec3<f32>(1f, 1f, 1f) - _e381);
    lobe3_.kind = 4i;
    lobe3_.mode = 1i;
    let _e385 = v52_;
    param_237 = _e385;
    let _e387 = (*g_1).N;
    param_238 = _e387;
    let _e388 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_237), (&param_238));
    lobe3_.N = _e388;
    let _e391 = (*g_1).T;
    lobe3_.T = _e391;
    lobe3_.alpha = vec2<f32>(0f, 0f);
    lobe3_.eta = 1.5f;
    let _e395 = v46_;
    lobe3_.c0_ = _e395;
    lobe3_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.p0_ = 0f;
    lobe3_.p1_ = 1f;
    lobe3_.film = vec3<f32>(0f, 0f, 0f);
    lobe3_.tau = vec3<f32>(0f, 0f, 0f);
    lobe3_.tauEta = 1f;
    lobe0_.weight = vec3<f32>(1f, 1f, 1f);
    let _e405 = lobe0_;
    (*c_9).lobes[0i] = _e405;
    let _e408 = w2_;
    lobe3_.weight = _e408;
    let _e410 = lobe3_;
    (*c_9).lobes[1i] = _e410;
    (*c_9).count = 2i;
    let _e414 = (*c_9);
    param_239 = _e414;
    let _e415 = (*wo_15);
    param_240 = _e415;
    mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b((&param_239), (&param_240));
    let _e416 = param_239;
    (*c_9) = _e416;
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
    var handedness: f32;
    var frame_4: mat3x3<f32>;
    var param_243: vec3<f32>;
    var param_244: vec3<f32>;
    var param_245: vec3<f32>;
    var param_246: vec3<f32>;
    var objectFrame: mat3x3<f32>;
    var param_247: vec3<f32>;
    var param_248: vec3<f32>;
    var wo_16: vec3<f32>;
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
    var phi_641_: bool;
    var phi_652_: bool;
    var phi_714_: bool;
    var phi_771_: bool;
    var phi_772_: bool;
    var phi_805_: bool;
    var phi_847_: bool;

    mxc_texture_footprint = 1f;
    let _e263 = vPosition_1;
    g_2.P = _e263;
    let _e265 = vObjectPosition_1;
    g_2.Pobj = _e265;
    let _e267 = vNormal_1;
    param_241 = _e267;
    param_242 = vec3<f32>(0f, 0f, 1f);
    let _e268 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_241), (&param_242));
    N_2 = _e268;
    let _e269 = gl_FrontFacing_1;
    if !(_e269) {
        let _e271 = N_2;
        N_2 = -(_e271);
    }
    let _e274 = vTangent_1[3u];
    handedness = select(1f, -1f, (_e274 < 0f));
    let _e277 = N_2;
    param_243 = _e277;
    let _e278 = vTangent_1;
    param_244 = _e278.xyz;
    let _e280 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_243), (&param_244));
    frame_4 = _e280;
    let _e281 = N_2;
    g_2.N = _e281;
    let _e284 = frame_4[0];
    g_2.T = _e284;
    let _e287 = frame_4[1];
    let _e288 = handedness;
    g_2.B = (_e287 * _e288);
    let _e291 = vObjectNormal_1;
    param_245 = _e291;
    param_246 = vec3<f32>(0f, 0f, 1f);
    let _e292 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_245), (&param_246));
    g_2.Nobj = _e292;
    let _e295 = g_2.Nobj;
    param_247 = _e295;
    let _e296 = vObjectTangent_1;
    param_248 = _e296;
    let _e297 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_247), (&param_248));
    objectFrame = _e297;
    let _e299 = objectFrame[0];
    g_2.Tobj = _e299;
    let _e302 = objectFrame[1];
    let _e303 = handedness;
    g_2.Bobj = (_e302 * _e303);
    let _e306 = vUv_1;
    g_2.uv = _e306;
    g_2.color = vec4<f32>(1f, 1f, 1f, 1f);
    let _e310 = mxc_view.objectToWorld;
    g_2.objectToWorld = _e310;
    let _e313 = mxc_params.frame;
    g_2.frame = _e313;
    let _e316 = mxc_params.time;
    g_2.time = _e316;
    let _e319 = mxc_view.eye;
    let _e321 = vPosition_1;
    param_249 = (_e319.xyz - _e321);
    let _e323 = N_2;
    param_250 = _e323;
    let _e324 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_249), (&param_250));
    wo_16 = _e324;
    let _e327 = mxc_view.jitter[2u];
    mxc_texture_footprint = _e327;
    let _e328 = mxc_texture_footprint;
    if !((_e328 > 0f)) {
        mxc_texture_footprint = 1f;
    }
    let _e332 = gl_FragCoord_1[0u];
    let _e335 = gl_FragCoord_1[1u];
    let _e339 = mxc_view.counts[2u];
    param_251 = (bitcast<u32>(_e339) + 7u);
    let _e342 = mxc_pcg_u0028_u1_u003b((&param_251));
    param_252 = (u32(_e335) + _e342);
    let _e344 = mxc_pcg_u0028_u1_u003b((&param_252));
    param_253 = (u32(_e332) ^ _e344);
    let _e346 = mxc_pcg_u0028_u1_u003b((&param_253));
    param_254 = _e346;
    mxc_closure_seed_u0028_u1_u003b((&param_254));
    let _e347 = g_2;
    param_255 = _e347;
    let _e348 = wo_16;
    param_256 = _e348;
    mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b((&param_255), (&param_256), (&param_257));
    let _e349 = param_257;
    c_10 = _e349;
    let _e351 = c_10.emission;
    let _e354 = mxc_view.environment[1u];
    radiance = (_e351 * _e354);
    let _e356 = mxc_light_count_u0028_();
    lights = _e356;
    let _e357 = mxc_light_kinds_u0028_();
    kinds = _e357;
    let _e358 = mxc_environment_code_u0028_();
    image = (_e358 == 3i);
    let _e360 = mxc_environment_code_u0028_();
    if (_e360 != 0i) {
        let _e364 = mxc_view.counts[3u];
        local_23 = max(_e364, 1i);
    } else {
        local_23 = 0i;
    }
    let _e366 = local_23;
    n_1 = _e366;
    let _e368 = gl_FragCoord_1[0u];
    let _e371 = gl_FragCoord_1[1u];
    let _e375 = mxc_view.counts[2u];
    param_258 = bitcast<u32>(_e375);
    let _e377 = mxc_pcg_u0028_u1_u003b((&param_258));
    param_259 = (u32(_e371) + _e377);
    let _e379 = mxc_pcg_u0028_u1_u003b((&param_259));
    param_260 = (u32(_e368) + _e379);
    let _e381 = mxc_pcg_u0028_u1_u003b((&param_260));
    seed_2 = _e381;
    let _e383 = gl_FragCoord_1[0u];
    let _e386 = gl_FragCoord_1[1u];
    param_261 = (u32(_e386) + 2654435769u);
    let _e389 = mxc_pcg_u0028_u1_u003b((&param_261));
    param_262 = (u32(_e383) ^ _e389);
    let _e391 = mxc_pcg_u0028_u1_u003b((&param_262));
    pixel = _e391;
    let _e392 = pixel;
    param_263 = _e392;
    let _e393 = mxc_uniform_u0028_u1_u003b((&param_263));
    let _e394 = param_263;
    pixel = _e394;
    let _e395 = pixel;
    param_264 = _e395;
    let _e396 = mxc_uniform_u0028_u1_u003b((&param_264));
    let _e397 = param_264;
    pixel = _e397;
    let _e398 = pixel;
    param_265 = _e398;
    let _e399 = mxc_uniform_u0028_u1_u003b((&param_265));
    let _e400 = param_265;
    pixel = _e400;
    let _e401 = pixel;
    param_266 = _e401;
    let _e402 = mxc_uniform_u0028_u1_u003b((&param_266));
    let _e403 = param_266;
    pixel = _e403;
    shift = vec4<f32>(_e393, _e396, _e399, _e402);
    sum = vec3<f32>(0f, 0f, 0f);
    b_3 = 0i;
    loop {
        let _e405 = b_3;
        let _e406 = n_1;
        let _e407 = lights;
        if (_e405 < max(_e406, select(0i, 1i, (_e407 > 0i)))) {
            let _e412 = b_3;
            let _e414 = lights;
            batchLights = select(0i, _e414, (_e412 == 0i));
            let _e416 = b_3;
            let _e417 = n_1;
            if (_e416 < _e417) {
                let _e419 = image;
                local_24 = (1i + select(0i, 1i, _e419));
            } else {
                local_24 = 0i;
            }
            let _e422 = local_24;
            batchSamples = _e422;
            let _e425 = mxc_view.counts[2u];
            let _e427 = n_1;
            let _e431 = b_3;
            index = ((bitcast<u32>(_e425) * bitcast<u32>(max(_e427, 1i))) + bitcast<u32>(_e431));
            let _e434 = index;
            param_267 = _e434;
            param_268 = 2u;
            let _e435 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_267), (&param_268));
            let _e436 = index;
            param_269 = _e436;
            param_270 = 3u;
            let _e437 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_269), (&param_270));
            let _e438 = index;
            param_271 = _e438;
            param_272 = 5u;
            let _e439 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_271), (&param_272));
            let _e440 = index;
            param_273 = _e440;
            param_274 = 7u;
            let _e441 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_273), (&param_274));
            let _e443 = shift;
            choice = fract((vec4<f32>(_e435, _e437, _e439, _e441) + _e443));
            smp.valid = false;
            smp.evaluate = false;
            smp.delta = false;
            smp.pdf = 0f;
            smp.weight = vec3<f32>(0f, 0f, 0f);
            let _e451 = N_2;
            smp.wi = _e451;
            let _e453 = n_1;
            if (_e453 > 0i) {
                let _e456 = choice[2u];
                let _e458 = choice[3u];
                let _e460 = choice[0u];
                let _e462 = c_10;
                param_275 = _e462;
                let _e463 = wo_16;
                param_276 = _e463;
                param_277 = vec3<f32>(_e456, _e458, _e460);
                let _e464 = mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b((&param_275), (&param_276), (&param_277));
                smp = _e464;
            }
            let _e466 = smp.wi;
            let _e467 = N_2;
            above_4 = (dot(_e466, _e467) > 0f);
            let _e471 = smp.valid;
            if _e471 {
                let _e472 = above_4;
                if _e472 {
                    let _e474 = smp.wi;
                    local_26 = _e474;
                } else {
                    let _e475 = wo_16;
                    param_278 = -(_e475);
                    let _e478 = smp.wi;
                    param_279 = _e478;
                    let _e479 = mxc_exit_direction_u0028_vf3_u003b_vf3_u003b((&param_278), (&param_279));
                    local_26 = _e479;
                }
                let _e480 = local_26;
                param_280 = _e480;
                let _e481 = mxc_environment_u0028_vf3_u003b((&param_280));
                local_25 = _e481;
            } else {
                local_25 = vec3<f32>(0f, 0f, 0f);
            }
            let _e482 = local_25;
            seen = _e482;
            let _e483 = b_3;
            let _e484 = n_1;
            let _e487 = smp.valid;
            let _e488 = ((_e483 < _e484) && _e487);
            phi_641_ = _e488;
            if _e488 {
                let _e490 = smp.evaluate;
                phi_641_ = !(_e490);
            }
            let _e493 = phi_641_;
            if _e493 {
                let _e494 = image;
                let _e495 = above_4;
                let _e496 = (_e494 && _e495);
                phi_652_ = _e496;
                if _e496 {
                    let _e498 = smp.delta;
                    phi_652_ = !(_e498);
                }
                let _e501 = phi_652_;
                if _e501 {
                    let _e503 = smp.wi;
                    param_281 = _e503;
                    let _e506 = mxc_view.environment[2u];
                    param_282 = _e506;
                    let _e507 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_281), (&param_282));
                    param_283 = _e507;
                    let _e508 = mxc_env_pdf_u0028_vf3_u003b((&param_283));
                    let _e510 = smp.pdf;
                    param_284 = _e510;
                    param_285 = _e508;
                    let _e511 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_284), (&param_285));
                    local_27 = _e511;
                } else {
                    local_27 = 1f;
                }
                let _e512 = local_27;
                w_1 = _e512;
                let _e513 = w_1;
                let _e515 = smp.weight;
                let _e517 = seen;
                let _e519 = sum;
                sum = (_e519 + ((_e515 * _e513) * _e517));
            }
            m_5 = vec3<f32>(0f, 0f, 0f);
            lightPdf = 0f;
            let _e521 = N_2;
            imageWi = _e521;
            imageSeen = vec3<f32>(0f, 0f, 0f);
            let _e522 = image;
            let _e523 = b_3;
            let _e524 = n_1;
            if (_e522 && (_e523 < _e524)) {
                let _e528 = choice[1u];
                let _e529 = seed_2;
                param_286 = _e529;
                let _e530 = mxc_uniform_u0028_u1_u003b((&param_286));
                let _e531 = param_286;
                seed_2 = _e531;
                let _e532 = seed_2;
                param_287 = _e532;
                let _e533 = mxc_uniform_u0028_u1_u003b((&param_287));
                let _e534 = param_287;
                seed_2 = _e534;
                let _e535 = seed_2;
                param_288 = _e535;
                let _e536 = mxc_uniform_u0028_u1_u003b((&param_288));
                let _e537 = param_288;
                seed_2 = _e537;
                v_8 = vec4<f32>(_e528, _e530, _e533, _e536);
                let _e539 = v_8;
                param_289 = _e539;
                let _e540 = mxc_env_sample_u0028_vf4_u003b_f1_u003b((&param_289), (&param_290));
                let _e541 = param_290;
                lightPdf = _e541;
                m_5 = _e540;
                let _e542 = m_5;
                param_291 = _e542;
                let _e545 = mxc_view.environment[2u];
                param_292 = _e545;
                let _e546 = mxc_env_to_world_u0028_vf3_u003b_f1_u003b((&param_291), (&param_292));
                imageWi = _e546;
                let _e547 = lightPdf;
                let _e548 = (_e547 > 0f);
                phi_714_ = _e548;
                if _e548 {
                    let _e549 = imageWi;
                    let _e550 = N_2;
                    phi_714_ = (dot(_e549, _e550) > 0f);
                }
                let _e554 = phi_714_;
                if _e554 {
                    let _e555 = imageWi;
                    param_293 = _e555;
                    let _e556 = mxc_environment_u0028_vf3_u003b((&param_293));
                    imageSeen = _e556;
                }
            }
            j_2 = 0i;
            loop {
                let _e557 = j_2;
                let _e558 = batchLights;
                let _e559 = batchSamples;
                if (_e557 < (_e558 + _e559)) {
                    let _e562 = N_2;
                    wi_6 = _e562;
                    incoming = vec3<f32>(0f, 0f, 0f);
                    use_ = true;
                    let _e563 = n_1;
                    let _e565 = j_2;
                    let _e566 = batchLights;
                    if ((_e563 == 0i) || (_e565 < _e566)) {
                        local_28 = 0i;
                    } else {
                        let _e569 = j_2;
                        let _e570 = batchLights;
                        local_28 = select(2i, 1i, (_e569 == ((_e570 + 1i) - 1i)));
                    }
                    let _e575 = local_28;
                    strategy = _e575;
                    let _e576 = strategy;
                    if (_e576 == 0i) {
                        let _e578 = j_2;
                        let _e581 = mxc_view.lightVector[_e578];
                        light = _e581;
                        let _e582 = j_2;
                        let _e585 = mxc_view.lightRadiance[_e582];
                        incoming = _e585.xyz;
                        let _e587 = kinds;
                        let _e588 = (_e587 == 1i);
                        phi_772_ = _e588;
                        if !(_e588) {
                            let _e590 = kinds;
                            let _e592 = ((_e590 & 1i) != 0i);
                            phi_771_ = _e592;
                            if _e592 {
                                let _e594 = light[3u];
                                phi_771_ = (_e594 == 0f);
                            }
                            let _e597 = phi_771_;
                            phi_772_ = _e597;
                        }
                        let _e599 = phi_772_;
                        directional = _e599;
                        let _e600 = directional;
                        if _e600 {
                            let _e601 = light;
                            param_294 = _e601.xyz;
                            let _e603 = N_2;
                            param_295 = _e603;
                            let _e604 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_294), (&param_295));
                            wi_6 = _e604;
                        } else {
                            let _e605 = light;
                            let _e607 = vPosition_1;
                            d_8 = (_e605.xyz - _e607);
                            let _e609 = d_8;
                            let _e610 = d_8;
                            d2_ = max(dot(_e609, _e610), 0.00000001f);
                            let _e613 = d_8;
                            let _e614 = d2_;
                            wi_6 = (_e613 * inverseSqrt(_e614));
                            let _e617 = d2_;
                            let _e618 = incoming;
                            incoming = (_e618 / vec3(_e617));
                            let _e621 = kinds;
                            let _e623 = ((_e621 & 4i) != 0i);
                            phi_805_ = _e623;
                            if _e623 {
                                let _e625 = light[3u];
                                phi_805_ = (_e625 == 2f);
                            }
                            let _e628 = phi_805_;
                            if _e628 {
                                let _e629 = j_2;
                                let _e632 = mxc_view.lightSpot[_e629];
                                spot = _e632;
                                let _e634 = spot[3u];
                                let _e635 = j_2;
                                let _e639 = mxc_view.lightRadiance[_e635][3u];
                                let _e640 = wi_6;
                                let _e642 = spot;
                                let _e646 = incoming;
                                incoming = (_e646 * smoothstep(_e634, _e639, dot(-(_e640), _e642.xyz)));
                            }
                        }
                    } else {
                        let _e648 = strategy;
                        if (_e648 == 1i) {
                            let _e651 = smp.wi;
                            wi_6 = _e651;
                            let _e652 = seen;
                            incoming = _e652;
                            let _e654 = smp.valid;
                            let _e656 = smp.evaluate;
                            use_ = (_e654 && _e656);
                        } else {
                            let _e658 = imageWi;
                            wi_6 = _e658;
                            let _e659 = imageSeen;
                            incoming = _e659;
                            let _e660 = lightPdf;
                            let _e661 = (_e660 > 0f);
                            phi_847_ = _e661;
                            if _e661 {
                                let _e662 = imageWi;
                                let _e663 = N_2;
                                phi_847_ = (dot(_e662, _e663) > 0f);
                            }
                            let _e667 = phi_847_;
                            use_ = _e667;
                        }
                    }
                    let _e668 = strategy;
                    let _e670 = c_10;
                    param_296 = _e670;
                    let _e671 = wo_16;
                    param_297 = _e671;
                    let _e672 = wi_6;
                    param_298 = _e672;
                    param_299 = (_e668 != 0i);
                    let _e673 = mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b((&param_296), (&param_297), (&param_298), (&param_299), (&param_300));
                    let _e674 = param_300;
                    pdf_2 = _e674;
                    f_5 = _e673;
                    let _e675 = strategy;
                    if (_e675 == 0i) {
                        let _e677 = f_5;
                        let _e678 = incoming;
                        let _e680 = radiance;
                        radiance = (_e680 + (_e677 * _e678));
                    } else {
                        let _e682 = strategy;
                        if (_e682 == 1i) {
                            let _e684 = use_;
                            let _e685 = pdf_2;
                            if (_e684 && (_e685 > 0f)) {
                                let _e688 = image;
                                let _e689 = above_4;
                                if (_e688 && _e689) {
                                    let _e691 = wi_6;
                                    param_301 = _e691;
                                    let _e694 = mxc_view.environment[2u];
                                    param_302 = _e694;
                                    let _e695 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_301), (&param_302));
                                    param_303 = _e695;
                                    let _e696 = mxc_env_pdf_u0028_vf3_u003b((&param_303));
                                    let _e697 = pdf_2;
                                    param_304 = _e697;
                                    param_305 = _e696;
                                    let _e698 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_304), (&param_305));
                                    local_29 = _e698;
                                } else {
                                    local_29 = 1f;
                                }
                                let _e699 = local_29;
                                w_2 = _e699;
                                let _e700 = w_2;
                                let _e701 = f_5;
                                let _e703 = pdf_2;
                                let _e706 = incoming;
                                let _e708 = sum;
                                sum = (_e708 + (((_e701 * _e700) / vec3(_e703)) * _e706));
                            }
                        } else {
                            let _e710 = use_;
                            if _e710 {
                                let _e711 = m_5;
                                param_306 = _e711;
                                let _e712 = mxc_env_pdf_u0028_vf3_u003b((&param_306));
                                param_307 = _e712;
                                let _e713 = pdf_2;
                                param_308 = _e713;
                                let _e714 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_307), (&param_308));
                                w_3 = _e714;
                                let _e715 = w_3;
                                let _e716 = f_5;
                                let _e718 = incoming;
                                let _e720 = lightPdf;
                                let _e723 = sum;
                                sum = (_e723 + (((_e716 * _e715) * _e718) / vec3(_e720)));
                            }
                        }
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e725 = j_2;
                    j_2 = (_e725 + 1i);
                }
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e727 = b_3;
            b_3 = (_e727 + 1i);
        }
    }
    let _e729 = sum;
    let _e730 = n_1;
    let _e735 = radiance;
    radiance = (_e735 + (_e729 / vec3(f32(max(_e730, 1i)))));
    let _e738 = c_10.transparency;
    param_309 = _e738;
    let _e739 = mxc_luminance_u0028_vf3_u003b((&param_309));
    coverage = (1f - clamp(_e739, 0f, 1f));
    let _e742 = radiance;
    let _e743 = coverage;
    outColor = vec4<f32>(_e742.x, _e742.y, _e742.z, _e743);
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
