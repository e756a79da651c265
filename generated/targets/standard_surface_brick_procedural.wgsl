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
    let _e154 = (*c);
    return dot(_e154, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b(l: ptr<function, MxcLobe>, mu: ptr<function, f32>) -> vec3<f32> {
    return vec3<f32>(1f, 1f, 1f);
}

fn mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_1: ptr<function, MxcLobe>) -> bool {
    return false;
}

fn mxc_mean_u0028_vf3_u003b(c_1: ptr<function, vec3<f32>>) -> f32 {
    let _e155 = (*c_1)[0u];
    let _e157 = (*c_1)[1u];
    let _e160 = (*c_1)[2u];
    return (((_e155 + _e157) + _e160) * 0.33333334f);
}

fn mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b(cosi: ptr<function, f32>, eta: ptr<function, f32>) -> f32 {
    var sin2t: f32;
    var cost: f32;
    var rs: f32;
    var rp: f32;

    let _e159 = (*eta);
    if (abs((_e159 - 1f)) < 0.000001f) {
        return 0f;
    }
    let _e163 = (*cosi);
    let _e164 = (*cosi);
    let _e167 = (*eta);
    let _e168 = (*eta);
    sin2t = ((1f - (_e163 * _e164)) / (_e167 * _e168));
    let _e171 = sin2t;
    if (_e171 >= 1f) {
        return 1f;
    }
    let _e173 = sin2t;
    cost = sqrt((1f - _e173));
    let _e176 = (*cosi);
    let _e177 = (*eta);
    let _e178 = cost;
    let _e181 = (*cosi);
    let _e182 = (*eta);
    let _e183 = cost;
    rs = ((_e176 - (_e177 * _e178)) / (_e181 + (_e182 * _e183)));
    let _e187 = (*eta);
    let _e188 = (*cosi);
    let _e190 = cost;
    let _e192 = (*eta);
    let _e193 = (*cosi);
    let _e195 = cost;
    rp = (((_e187 * _e188) - _e190) / ((_e192 * _e193) + _e195));
    let _e198 = rs;
    let _e199 = rs;
    let _e201 = rp;
    let _e202 = rp;
    return (0.5f * ((_e198 * _e199) + (_e201 * _e202)));
}

fn mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_2: ptr<function, MxcLobe>, above: ptr<function, bool>) -> f32 {
    var local: f32;

    let _e156 = (*above);
    if _e156 {
        let _e158 = (*l_2).eta;
        local = _e158;
    } else {
        let _e160 = (*l_2).eta;
        local = (1f / _e160);
    }
    let _e162 = local;
    return _e162;
}

fn mxc_lobe_cosine_below_coat_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b(l_3: ptr<function, MxcLobe>, mu_1: ptr<function, f32>) -> f32 {
    var phi_1988_: bool;

    let _e156 = (*l_3).kind;
    let _e157 = (_e156 == 1i);
    phi_1988_ = _e157;
    if _e157 {
        let _e159 = (*l_3).etaAbove;
        phi_1988_ = (_e159 > 1f);
    }
    let _e162 = phi_1988_;
    if _e162 {
        let _e163 = (*mu_1);
        let _e164 = (*mu_1);
        let _e168 = (*l_3).etaAbove;
        let _e170 = (*l_3).etaAbove;
        return sqrt((1f - ((1f - (_e163 * _e164)) / (_e168 * _e170))));
    }
    let _e175 = (*mu_1);
    return _e175;
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
    let _e163 = (*above_1);
    if _e163 {
        let _e164 = (*cosh_);
        let _e166 = (*l_4);
        param = _e166;
        param_1 = clamp(_e164, 0f, 1f);
        let _e167 = mxc_lobe_cosine_below_coat_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param), (&param_1));
        (*cosh_) = _e167;
    }
    let _e169 = (*l_4).kind;
    if (_e169 == 1i) {
        let _e171 = (*l_4);
        param_2 = _e171;
        let _e172 = (*above_1);
        param_3 = _e172;
        let _e173 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_2), (&param_3));
        let _e174 = (*cosh_);
        param_4 = _e174;
        param_5 = _e173;
        let _e175 = mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b((&param_4), (&param_5));
        f = vec3(_e175);
    }
    let _e177 = f;
    return _e177;
}

fn mxc_rough_alpha_u0028_vf2_u003b(alpha: ptr<function, vec2<f32>>) -> vec2<f32> {
    let _e154 = (*alpha);
    return max(_e154, vec2<f32>(0.0001f, 0.0001f));
}

fn mxc_ggx_d_u0028_vf3_u003b_vf2_u003b(m: ptr<function, vec3<f32>>, alpha_1: ptr<function, vec2<f32>>) -> f32 {
    var param_6: vec2<f32>;
    var s: vec3<f32>;
    var d: f32;

    let _e159 = (*m)[2u];
    if (_e159 <= 0f) {
        return 0f;
    }
    let _e161 = (*alpha_1);
    param_6 = _e161;
    let _e162 = mxc_rough_alpha_u0028_vf2_u003b((&param_6));
    (*alpha_1) = _e162;
    let _e164 = (*m)[0u];
    let _e166 = (*alpha_1)[0u];
    let _e169 = (*m)[1u];
    let _e171 = (*alpha_1)[1u];
    let _e174 = (*m)[2u];
    s = vec3<f32>((_e164 / _e166), (_e169 / _e171), _e174);
    let _e176 = s;
    let _e177 = s;
    d = dot(_e176, _e177);
    let _e180 = (*alpha_1)[0u];
    let _e183 = (*alpha_1)[1u];
    let _e185 = d;
    let _e187 = d;
    return (1f / ((((3.1415927f * _e180) * _e183) * _e185) * _e187));
}

fn mxc_sqr_u0028_f1_u003b(x: ptr<function, f32>) -> f32 {
    let _e154 = (*x);
    let _e155 = (*x);
    return (_e154 * _e155);
}

fn mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b(v: ptr<function, vec3<f32>>, alpha_2: ptr<function, vec2<f32>>) -> f32 {
    var param_7: vec2<f32>;
    var z2_: f32;
    var a2_: f32;
    var param_8: f32;
    var param_9: f32;

    let _e160 = (*alpha_2);
    param_7 = _e160;
    let _e161 = mxc_rough_alpha_u0028_vf2_u003b((&param_7));
    (*alpha_2) = _e161;
    let _e163 = (*v)[2u];
    let _e165 = (*v)[2u];
    z2_ = (_e163 * _e165);
    let _e167 = z2_;
    if (_e167 <= 0f) {
        return 10000000000f;
    }
    let _e170 = (*alpha_2)[0u];
    let _e172 = (*v)[0u];
    param_8 = (_e170 * _e172);
    let _e174 = mxc_sqr_u0028_f1_u003b((&param_8));
    let _e176 = (*alpha_2)[1u];
    let _e178 = (*v)[1u];
    param_9 = (_e176 * _e178);
    let _e180 = mxc_sqr_u0028_f1_u003b((&param_9));
    let _e182 = z2_;
    a2_ = ((_e174 + _e180) / _e182);
    let _e184 = a2_;
    return (0.5f * (-1f + sqrt((1f + _e184))));
}

fn mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b(v_1: ptr<function, vec3<f32>>, alpha_3: ptr<function, vec2<f32>>) -> f32 {
    var param_10: vec3<f32>;
    var param_11: vec2<f32>;

    let _e157 = (*v_1);
    param_10 = _e157;
    let _e158 = (*alpha_3);
    param_11 = _e158;
    let _e159 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_10), (&param_11));
    return (1f / (1f + _e159));
}

fn mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo: ptr<function, vec3<f32>>, m_1: ptr<function, vec3<f32>>, alpha_4: ptr<function, vec2<f32>>) -> f32 {
    var param_12: vec3<f32>;
    var param_13: vec2<f32>;
    var param_14: vec3<f32>;
    var param_15: vec2<f32>;

    let _e161 = (*wo)[2u];
    if (_e161 <= 0f) {
        return 0f;
    }
    let _e163 = (*wo);
    param_12 = _e163;
    let _e164 = (*alpha_4);
    param_13 = _e164;
    let _e165 = mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b((&param_12), (&param_13));
    let _e166 = (*wo);
    let _e167 = (*m_1);
    let _e171 = (*m_1);
    param_14 = _e171;
    let _e172 = (*alpha_4);
    param_15 = _e172;
    let _e173 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_14), (&param_15));
    let _e176 = (*wo)[2u];
    return (((_e165 * max(dot(_e166, _e167), 0f)) * _e173) / _e176);
}

fn mxc_is_delta_u0028_vf2_u003b(alpha_5: ptr<function, vec2<f32>>) -> bool {
    let _e155 = (*alpha_5)[0u];
    let _e157 = (*alpha_5)[1u];
    return (max(_e155, _e157) < 0.0001f);
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
    var phi_2894_: bool;
    var phi_2975_: bool;

    let _e175 = (*l_5).kind;
    switch _e175 {
        case 2, 3, 1: {
            let _e189 = (*l_5).alpha;
            param_16 = _e189;
            let _e190 = mxc_is_delta_u0028_vf2_u003b((&param_16));
            if _e190 {
                return 0f;
            }
            let _e192 = (*wo_1)[2u];
            above_2 = (_e192 > 0f);
            let _e194 = above_2;
            if _e194 {
                let _e195 = (*wo_1);
                local_1 = _e195;
            } else {
                let _e196 = (*wo_1);
                local_1 = -(_e196);
            }
            let _e198 = local_1;
            o = _e198;
            let _e199 = above_2;
            if _e199 {
                let _e200 = (*wi);
                local_2 = _e200;
            } else {
                let _e201 = (*wi);
                local_2 = -(_e201);
            }
            let _e203 = local_2;
            i = _e203;
            let _e205 = i[2u];
            if (_e205 > 0f) {
                let _e207 = o;
                let _e208 = i;
                h = normalize((_e207 + _e208));
                let _e211 = o;
                param_17 = _e211;
                let _e212 = h;
                param_18 = _e212;
                let _e214 = (*l_5).alpha;
                param_19 = _e214;
                let _e215 = mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_17), (&param_18), (&param_19));
                let _e216 = o;
                let _e217 = h;
                p = (_e215 / (4f * max(dot(_e216, _e217), 0.000001f)));
                let _e223 = (*l_5).kind;
                if (_e223 == 2i) {
                    let _e225 = p;
                    return _e225;
                }
                let _e227 = (*l_5).mode;
                if ((_e227 & 1i) == 0i) {
                    return 0f;
                }
                let _e230 = o;
                let _e231 = h;
                let _e234 = (*l_5);
                param_20 = _e234;
                param_21 = max(dot(_e230, _e231), 0f);
                let _e235 = above_2;
                param_22 = _e235;
                let _e236 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_20), (&param_21), (&param_22));
                param_23 = _e236;
                let _e237 = mxc_mean_u0028_vf3_u003b((&param_23));
                fr = _e237;
                let _e238 = p;
                let _e239 = (*l_5);
                param_24 = _e239;
                let _e240 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_24));
                phi_2975_ = _e240;
                if _e240 {
                    let _e242 = (*l_5).mode;
                    phi_2975_ = ((_e242 & 1i) != 0i);
                }
                let _e246 = phi_2975_;
                let _e247 = fr;
                return (_e238 * select(1f, _e247, _e246));
            }
            return 0f;
        }
        default: {
            let _e177 = (*wo_1)[2u];
            let _e178 = (_e177 > 0f);
            phi_2894_ = _e178;
            if _e178 {
                let _e180 = (*wi)[2u];
                phi_2894_ = (_e180 > 0f);
            }
            let _e183 = phi_2894_;
            if _e183 {
                let _e185 = (*wi)[2u];
                local_3 = (_e185 * 0.31830987f);
            } else {
                local_3 = 0f;
            }
            let _e187 = local_3;
            return _e187;
        }
    }
}

fn mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b(sigma: ptr<function, f32>, wo_2: ptr<function, vec3<f32>>, wi_1: ptr<function, vec3<f32>>) -> f32 {
    var a: f32;
    var s_1: f32;
    var t: f32;
    var local_4: f32;

    let _e160 = (*sigma);
    a = (1f / (1f + (0.2877934f * _e160)));
    let _e164 = (*wi_1);
    let _e165 = (*wo_2);
    let _e168 = (*wi_1)[2u];
    let _e170 = (*wo_2)[2u];
    s_1 = (dot(_e164, _e165) - (_e168 * _e170));
    let _e173 = s_1;
    if (_e173 > 0f) {
        let _e176 = (*wi_1)[2u];
        let _e178 = (*wo_2)[2u];
        local_4 = max(max(_e176, _e178), 0.000001f);
    } else {
        local_4 = 1f;
    }
    let _e181 = local_4;
    t = _e181;
    let _e182 = a;
    let _e183 = (*sigma);
    let _e184 = a;
    let _e186 = s_1;
    let _e188 = t;
    return ((_e182 + (((_e183 * _e184) * _e186) / _e188)) * 0.31830987f);
}

fn mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo_3: ptr<function, vec3<f32>>, wi_2: ptr<function, vec3<f32>>, alpha_6: ptr<function, vec2<f32>>) -> f32 {
    var param_25: vec3<f32>;
    var param_26: vec2<f32>;
    var param_27: vec3<f32>;
    var param_28: vec2<f32>;

    let _e160 = (*wo_3);
    param_25 = _e160;
    let _e161 = (*alpha_6);
    param_26 = _e161;
    let _e162 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_25), (&param_26));
    let _e164 = (*wi_2);
    param_27 = _e164;
    let _e165 = (*alpha_6);
    param_28 = _e165;
    let _e166 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_27), (&param_28));
    return (1f / ((1f + _e162) + _e166));
}

fn mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_6: ptr<function, MxcLobe>, wo_4: ptr<function, vec3<f32>>, wi_3: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_29: vec2<f32>;
    var h_1: vec3<f32>;
    var f_1: vec3<f32>;
    var param_30: MxcLobe;
    var param_31: f32;
    var param_32: bool;
    var param_33: vec3<f32>;
    var param_34: vec2<f32>;
    var param_35: vec3<f32>;
    var param_36: vec3<f32>;
    var param_37: vec2<f32>;
    var phi_2060_: bool;
    var phi_2067_: bool;

    let _e168 = (*wo_4)[2u];
    let _e169 = (_e168 <= 0f);
    phi_2060_ = _e169;
    if !(_e169) {
        let _e172 = (*wi_3)[2u];
        phi_2060_ = (_e172 <= 0f);
    }
    let _e175 = phi_2060_;
    phi_2067_ = _e175;
    if !(_e175) {
        let _e178 = (*l_6).alpha;
        param_29 = _e178;
        let _e179 = mxc_is_delta_u0028_vf2_u003b((&param_29));
        phi_2067_ = _e179;
    }
    let _e181 = phi_2067_;
    if _e181 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e182 = (*wo_4);
    let _e183 = (*wi_3);
    h_1 = normalize((_e182 + _e183));
    let _e186 = (*wo_4);
    let _e187 = h_1;
    let _e190 = (*l_6);
    param_30 = _e190;
    param_31 = max(dot(_e186, _e187), 0f);
    param_32 = true;
    let _e191 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_30), (&param_31), (&param_32));
    f_1 = _e191;
    let _e193 = (*l_6).kind;
    if (_e193 == 1i) {
        let _e196 = (*l_6).c0_;
        let _e197 = f_1;
        f_1 = (_e197 * _e196);
    }
    let _e199 = f_1;
    let _e200 = h_1;
    param_33 = _e200;
    let _e202 = (*l_6).alpha;
    param_34 = _e202;
    let _e203 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_33), (&param_34));
    let _e205 = (*wo_4);
    param_35 = _e205;
    let _e206 = (*wi_3);
    param_36 = _e206;
    let _e208 = (*l_6).alpha;
    param_37 = _e208;
    let _e209 = mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_35), (&param_36), (&param_37));
    let _e212 = (*wo_4)[2u];
    return (((_e199 * _e203) * _e209) / vec3((4f * _e212)));
}

fn mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_7: ptr<function, MxcLobe>, wo_5: ptr<function, vec3<f32>>, wi_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var m_2: MxcLobe;
    var param_38: MxcLobe;
    var param_39: vec3<f32>;
    var param_40: vec3<f32>;
    var param_41: MxcLobe;
    var param_42: vec3<f32>;
    var param_43: vec3<f32>;
    var param_44: MxcLobe;
    var param_45: vec3<f32>;
    var param_46: vec3<f32>;
    var local_5: vec3<f32>;
    var param_47: f32;
    var param_48: vec3<f32>;
    var param_49: vec3<f32>;
    var phi_2827_: bool;
    var phi_2842_: bool;

    let _e171 = (*l_7).kind;
    switch _e171 {
        case 1: {
            let _e173 = (*wo_5)[2u];
            let _e175 = (*wi_4)[2u];
            if ((_e173 * _e175) > 0f) {
                let _e179 = (*l_7).mode;
                if ((_e179 & 1i) == 0i) {
                    return vec3<f32>(0f, 0f, 0f);
                }
                let _e183 = (*wo_5)[2u];
                if (_e183 < 0f) {
                    let _e185 = (*l_7);
                    m_2 = _e185;
                    let _e187 = (*l_7).eta;
                    m_2.eta = (1f / _e187);
                    m_2.c0_ = vec3<f32>(1f, 1f, 1f);
                    let _e191 = (*wo_5);
                    let _e193 = (*wi_4);
                    let _e195 = m_2;
                    param_38 = _e195;
                    param_39 = -(_e191);
                    param_40 = -(_e193);
                    let _e196 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_38), (&param_39), (&param_40));
                    return _e196;
                }
                let _e197 = (*l_7);
                param_41 = _e197;
                let _e198 = (*wo_5);
                param_42 = _e198;
                let _e199 = (*wi_4);
                param_43 = _e199;
                let _e200 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_41), (&param_42), (&param_43));
                return _e200;
            }
            return vec3<f32>(0f, 0f, 0f);
        }
        case 3, 2: {
            let _e202 = (*l_7).kind;
            let _e203 = (_e202 == 3i);
            phi_2827_ = _e203;
            if _e203 {
                let _e205 = (*l_7).mode;
                phi_2827_ = ((_e205 & 1i) == 0i);
            }
            let _e209 = phi_2827_;
            if _e209 {
                return vec3<f32>(0f, 0f, 0f);
            }
            let _e210 = (*l_7);
            param_44 = _e210;
            let _e211 = (*wo_5);
            param_45 = _e211;
            let _e212 = (*wi_4);
            param_46 = _e212;
            let _e213 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_44), (&param_45), (&param_46));
            return _e213;
        }
        case 4: {
            let _e215 = (*wo_5)[2u];
            let _e216 = (_e215 > 0f);
            phi_2842_ = _e216;
            if _e216 {
                let _e218 = (*wi_4)[2u];
                phi_2842_ = (_e218 > 0f);
            }
            let _e221 = phi_2842_;
            if _e221 {
                let _e223 = (*l_7).c0_;
                let _e225 = (*l_7).p0_;
                param_47 = _e225;
                let _e226 = (*wo_5);
                param_48 = _e226;
                let _e227 = (*wi_4);
                param_49 = _e227;
                let _e228 = mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b((&param_47), (&param_48), (&param_49));
                let _e231 = (*wi_4)[2u];
                local_5 = ((_e223 * _e228) * _e231);
            } else {
                local_5 = vec3<f32>(0f, 0f, 0f);
            }
            let _e233 = local_5;
            return _e233;
        }
        default: {
            return vec3<f32>(0f, 0f, 0f);
        }
    }
}

fn mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_8: ptr<function, MxcLobe>, transmitted: ptr<function, bool>) -> MxcLobe {
    var m_3: MxcLobe;
    var local_6: i32;

    let _e157 = (*l_8);
    m_3 = _e157;
    let _e159 = (*l_8).alpha;
    let _e160 = (*transmitted);
    m_3.alpha = min((_e159 * select(1.5f, 3f, _e160)), vec2<f32>(1f, 1f));
    let _e165 = (*transmitted);
    if _e165 {
        let _e167 = (*l_8).mode;
        local_6 = (_e167 & -2i);
    } else {
        let _e170 = (*l_8).mode;
        local_6 = (_e170 & -3i);
    }
    let _e172 = local_6;
    m_3.mode = _e172;
    let _e175 = (*l_8).kind;
    if (_e175 == 1i) {
        m_3.c0_ = vec3<f32>(1f, 1f, 1f);
        m_3.c1_ = vec3<f32>(1f, 1f, 1f);
    }
    let _e179 = m_3;
    return _e179;
}

fn mxc_to_local_u0028_mf33_u003b_vf3_u003b(frame: ptr<function, mat3x3<f32>>, v_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e155 = (*v_2);
    let _e157 = (*frame)[0];
    let _e159 = (*v_2);
    let _e161 = (*frame)[1];
    let _e163 = (*v_2);
    let _e165 = (*frame)[2];
    return vec3<f32>(dot(_e155, _e157), dot(_e159, _e161), dot(_e163, _e165));
}

fn mxc_frame_u0028_vf3_u003b_vf3_u003b(N: ptr<function, vec3<f32>>, T: ptr<function, vec3<f32>>) -> mat3x3<f32> {
    var t_1: vec3<f32>;
    var l2_: f32;
    var s_2: f32;
    var a_1: f32;
    var b: f32;

    let _e160 = (*T);
    let _e161 = (*N);
    let _e162 = (*N);
    let _e163 = (*T);
    t_1 = (_e160 - (_e161 * dot(_e162, _e163)));
    let _e167 = t_1;
    let _e168 = t_1;
    l2_ = dot(_e167, _e168);
    let _e170 = l2_;
    if !((_e170 > 0.000000000001f)) {
        let _e174 = (*N)[2u];
        s_2 = select(-1f, 1f, (_e174 >= 0f));
        let _e177 = s_2;
        let _e179 = (*N)[2u];
        a_1 = (-1f / (_e177 + _e179));
        let _e183 = (*N)[0u];
        let _e185 = (*N)[1u];
        let _e187 = a_1;
        b = ((_e183 * _e185) * _e187);
        let _e189 = s_2;
        let _e191 = (*N)[0u];
        let _e194 = (*N)[0u];
        let _e196 = a_1;
        let _e199 = s_2;
        let _e200 = b;
        let _e202 = s_2;
        let _e205 = (*N)[0u];
        t_1 = vec3<f32>((1f + (((_e189 * _e191) * _e194) * _e196)), (_e199 * _e200), (-(_e202) * _e205));
    } else {
        let _e208 = l2_;
        let _e210 = t_1;
        t_1 = (_e210 * inverseSqrt(_e208));
    }
    let _e212 = t_1;
    let _e213 = (*N);
    let _e214 = t_1;
    let _e215 = cross(_e213, _e214);
    let _e216 = (*N);
    return mat3x3<f32>(vec3<f32>(_e212.x, _e212.y, _e212.z), vec3<f32>(_e215.x, _e215.y, _e215.z), vec3<f32>(_e216.x, _e216.y, _e216.z));
}

fn mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b(c_2: ptr<function, MxcClosure>, wo_6: ptr<function, vec3<f32>>, wi_5: ptr<function, vec3<f32>>, wantPdf: ptr<function, bool>, pdf: ptr<function, f32>) -> vec3<f32> {
    var f_2: vec3<f32>;
    var p_1: f32;
    var k: i32;
    var l_9: MxcLobe;
    var frame_1: mat3x3<f32>;
    var param_50: vec3<f32>;
    var param_51: vec3<f32>;
    var o_1: vec3<f32>;
    var param_52: mat3x3<f32>;
    var param_53: vec3<f32>;
    var i_1: vec3<f32>;
    var param_54: mat3x3<f32>;
    var param_55: vec3<f32>;
    var fk: vec3<f32>;
    var pk: f32;
    var passes: i32;
    var pass_: i32;
    var shaped: bool;
    var m_4: MxcLobe;
    var local_7: MxcLobe;
    var param_56: MxcLobe;
    var param_57: bool;
    var scale: vec3<f32>;
    var local_8: vec3<f32>;
    var local_9: vec3<f32>;
    var local_10: vec3<f32>;
    var param_58: MxcLobe;
    var param_59: vec3<f32>;
    var param_60: vec3<f32>;
    var share: f32;
    var local_11: f32;
    var local_12: f32;
    var param_61: MxcLobe;
    var param_62: vec3<f32>;
    var param_63: vec3<f32>;
    var param_64: MxcLobe;
    var param_65: f32;
    var local_13: f32;

    f_2 = vec3<f32>(0f, 0f, 0f);
    p_1 = 0f;
    k = 0i;
    loop {
        let _e196 = k;
        let _e198 = (*c_2).count;
        if (_e196 < _e198) {
            let _e200 = k;
            let _e203 = (*c_2).lobes[_e200];
            l_9 = _e203;
            let _e205 = l_9.weight;
            if all((_e205 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e209 = l_9.N;
            param_50 = _e209;
            let _e211 = l_9.T;
            param_51 = _e211;
            let _e212 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_50), (&param_51));
            frame_1 = _e212;
            let _e213 = frame_1;
            param_52 = _e213;
            let _e214 = (*wo_6);
            param_53 = _e214;
            let _e215 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_52), (&param_53));
            o_1 = _e215;
            let _e216 = frame_1;
            param_54 = _e216;
            let _e217 = (*wi_5);
            param_55 = _e217;
            let _e218 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_54), (&param_55));
            i_1 = _e218;
            fk = vec3<f32>(0f, 0f, 0f);
            pk = 0f;
            let _e219 = k;
            let _e222 = (*c_2).msPick[_e219];
            passes = select(1i, 2i, (_e222 > 0f));
            pass_ = 0i;
            loop {
                let _e225 = pass_;
                let _e226 = passes;
                if (_e225 < _e226) {
                    let _e228 = pass_;
                    shaped = (_e228 == 1i);
                    let _e230 = shaped;
                    if _e230 {
                        let _e232 = i_1[2u];
                        let _e234 = l_9;
                        param_56 = _e234;
                        param_57 = (_e232 < 0f);
                        let _e235 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_56), (&param_57));
                        local_7 = _e235;
                    } else {
                        let _e236 = l_9;
                        local_7 = _e236;
                    }
                    let _e237 = local_7;
                    m_4 = _e237;
                    let _e238 = shaped;
                    if _e238 {
                        let _e240 = i_1[2u];
                        if (_e240 > 0f) {
                            let _e242 = k;
                            let _e245 = (*c_2).msLobe[_e242];
                            local_9 = _e245;
                        } else {
                            let _e246 = k;
                            let _e249 = (*c_2).msLobeT[_e246];
                            local_9 = _e249;
                        }
                        let _e250 = local_9;
                        local_8 = _e250;
                    } else {
                        let _e252 = o_1[2u];
                        let _e254 = i_1[2u];
                        if ((_e252 * _e254) < 0f) {
                            let _e257 = k;
                            let _e260 = (*c_2).msT[_e257];
                            local_10 = vec3(_e260);
                        } else {
                            let _e262 = k;
                            let _e265 = (*c_2).ms[_e262];
                            local_10 = _e265;
                        }
                        let _e266 = local_10;
                        local_8 = _e266;
                    }
                    let _e267 = local_8;
                    scale = _e267;
                    let _e268 = scale;
                    let _e269 = m_4;
                    param_58 = _e269;
                    let _e270 = o_1;
                    param_59 = _e270;
                    let _e271 = i_1;
                    param_60 = _e271;
                    let _e272 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_58), (&param_59), (&param_60));
                    let _e274 = fk;
                    fk = (_e274 + (_e268 * _e272));
                    let _e276 = (*wantPdf);
                    if _e276 {
                        let _e277 = shaped;
                        if _e277 {
                            let _e278 = k;
                            let _e281 = (*c_2).msPick[_e278];
                            let _e283 = i_1[2u];
                            if (_e283 > 0f) {
                                let _e285 = k;
                                let _e288 = (*c_2).msSplit[_e285];
                                local_12 = _e288;
                            } else {
                                let _e289 = k;
                                let _e292 = (*c_2).msSplit[_e289];
                                local_12 = (1f - _e292);
                            }
                            let _e294 = local_12;
                            local_11 = (_e281 * _e294);
                        } else {
                            let _e296 = k;
                            let _e299 = (*c_2).msPick[_e296];
                            local_11 = (1f - _e299);
                        }
                        let _e301 = local_11;
                        share = _e301;
                        let _e302 = share;
                        let _e303 = m_4;
                        param_61 = _e303;
                        let _e304 = o_1;
                        param_62 = _e304;
                        let _e305 = i_1;
                        param_63 = _e305;
                        let _e306 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_61), (&param_62), (&param_63));
                        let _e308 = pk;
                        pk = (_e308 + (_e302 * _e306));
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e310 = pass_;
                    pass_ = (_e310 + 1i);
                }
            }
            let _e313 = l_9.weight;
            let _e315 = i_1[2u];
            let _e317 = l_9;
            param_64 = _e317;
            param_65 = abs(_e315);
            let _e318 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_64), (&param_65));
            let _e320 = fk;
            let _e322 = f_2;
            f_2 = (_e322 + ((_e313 * _e318) * _e320));
            let _e324 = (*wantPdf);
            if _e324 {
                let _e325 = k;
                let _e328 = (*c_2).choice[_e325];
                let _e329 = pk;
                let _e331 = p_1;
                p_1 = (_e331 + (_e328 * _e329));
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e333 = k;
            k = (_e333 + 1i);
        }
    }
    let _e336 = (*c_2).choiceTotal;
    if (_e336 > 0f) {
        let _e338 = p_1;
        let _e340 = (*c_2).choiceTotal;
        local_13 = (_e338 / _e340);
    } else {
        local_13 = 0f;
    }
    let _e342 = local_13;
    (*pdf) = _e342;
    let _e343 = f_2;
    return _e343;
}

fn mxc_env_to_world_u0028_vf3_u003b_f1_u003b(m_5: ptr<function, vec3<f32>>, angle: ptr<function, f32>) -> vec3<f32> {
    var c_3: f32;
    var s_3: f32;

    let _e157 = (*angle);
    c_3 = cos(_e157);
    let _e159 = (*angle);
    s_3 = sin(_e159);
    let _e161 = c_3;
    let _e163 = (*m_5)[0u];
    let _e165 = s_3;
    let _e167 = (*m_5)[2u];
    let _e171 = (*m_5)[1u];
    let _e172 = s_3;
    let _e175 = (*m_5)[0u];
    let _e177 = c_3;
    let _e179 = (*m_5)[2u];
    return vec3<f32>(((_e161 * _e163) + (_e165 * _e167)), _e171, ((-(_e172) * _e175) + (_e177 * _e179)));
}

fn mxc_safe_sqrt_u0028_f1_u003b(x_1: ptr<function, f32>) -> f32 {
    let _e154 = (*x_1);
    return sqrt(max(_e154, 0f));
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
    var param_66: f32;

    let _e168 = unnamed.mxc_env_size;
    size = max(_e168.xy, vec2<u32>(1u, 1u));
    let _e172 = size[0u];
    let _e174 = size[1u];
    n = (_e172 * _e174);
    let _e177 = (*u)[0u];
    let _e178 = n;
    let _e182 = n;
    k_1 = min(u32((_e177 * f32(_e178))), (_e182 - 1u));
    let _e185 = k_1;
    let _e188 = unnamed.mxc_env_cells[_e185];
    cell = _e188;
    let _e190 = (*u)[1u];
    let _e192 = cell[0u];
    if (_e190 >= _e192) {
        let _e195 = cell[1u];
        let _e197 = n;
        k_1 = min(bitcast<u32>(_e195), (_e197 - 1u));
    }
    let _e200 = k_1;
    let _e204 = unnamed.mxc_env_cells[_e200][2u];
    (*pdf_1) = _e204;
    let _e205 = k_1;
    let _e207 = size[0u];
    i_2 = (_e205 % _e207);
    let _e209 = k_1;
    let _e211 = size[0u];
    j = (_e209 / _e211);
    let _e213 = i_2;
    let _e216 = (*u)[2u];
    let _e219 = size[0u];
    phi = (6.2831855f * (((f32(_e213) + _e216) / f32(_e219)) - 0.5f));
    let _e224 = j;
    let _e228 = size[1u];
    y0_ = cos(((3.1415927f * f32(_e224)) / f32(_e228)));
    let _e232 = j;
    let _e237 = size[1u];
    y1_ = cos(((3.1415927f * f32((_e232 + 1u))) / f32(_e237)));
    let _e241 = y0_;
    let _e242 = y1_;
    let _e244 = (*u)[3u];
    y = mix(_e241, _e242, _e244);
    let _e246 = y;
    let _e247 = y;
    param_66 = (1f - (_e246 * _e247));
    let _e250 = mxc_safe_sqrt_u0028_f1_u003b((&param_66));
    r = _e250;
    let _e251 = r;
    let _e252 = phi;
    let _e255 = y;
    let _e256 = r;
    let _e258 = phi;
    return vec3<f32>((_e251 * sin(_e252)), _e255, (-(_e256) * cos(_e258)));
}

fn mxc_power_heuristic_u0028_f1_u003b_f1_u003b(a_2: ptr<function, f32>, b_1: ptr<function, f32>) -> f32 {
    var a2_1: f32;
    var b2_: f32;
    var local_14: f32;

    let _e158 = (*a_2);
    let _e159 = (*a_2);
    a2_1 = (_e158 * _e159);
    let _e161 = (*b_1);
    let _e162 = (*b_1);
    b2_ = (_e161 * _e162);
    let _e164 = a2_1;
    let _e165 = b2_;
    if ((_e164 + _e165) > 0f) {
        let _e168 = a2_1;
        let _e169 = a2_1;
        let _e170 = b2_;
        local_14 = (_e168 / (_e169 + _e170));
    } else {
        local_14 = 0f;
    }
    let _e173 = local_14;
    return _e173;
}

fn mxc_env_uv_u0028_vf3_u003b(d_1: ptr<function, vec3<f32>>) -> vec2<f32> {
    var u_1: f32;
    var local_15: f32;
    var v_3: f32;

    let _e158 = (*d_1)[0u];
    let _e161 = (*d_1)[2u];
    if ((abs(_e158) + abs(_e161)) > 0.000000000001f) {
        let _e166 = (*d_1)[0u];
        let _e168 = (*d_1)[2u];
        local_15 = (0.5f + (atan2(_e166, -(_e168)) * 0.15915494f));
    } else {
        local_15 = 0.5f;
    }
    let _e173 = local_15;
    u_1 = _e173;
    let _e174 = (*d_1);
    let _e178 = (*d_1)[1u];
    v_3 = (atan2(length(_e174.xz), _e178) * 0.31830987f);
    let _e181 = u_1;
    let _e182 = v_3;
    return vec2<f32>(_e181, _e182);
}

fn mxc_env_cell_u0028_vf3_u003b(d_2: ptr<function, vec3<f32>>) -> u32 {
    var uv: vec2<f32>;
    var param_67: vec3<f32>;
    var size_1: vec2<u32>;
    var i_3: u32;
    var j_1: u32;

    let _e159 = (*d_2);
    param_67 = _e159;
    let _e160 = mxc_env_uv_u0028_vf3_u003b((&param_67));
    uv = _e160;
    let _e162 = unnamed.mxc_env_size;
    size_1 = max(_e162.xy, vec2<u32>(1u, 1u));
    let _e166 = uv[0u];
    let _e169 = size_1[0u];
    let _e174 = size_1[0u];
    i_3 = min(u32((max(_e166, 0f) * f32(_e169))), (_e174 - 1u));
    let _e178 = uv[1u];
    let _e181 = size_1[1u];
    let _e186 = size_1[1u];
    j_1 = min(u32((max(_e178, 0f) * f32(_e181))), (_e186 - 1u));
    let _e189 = j_1;
    let _e191 = size_1[0u];
    let _e193 = i_3;
    return ((_e189 * _e191) + _e193);
}

fn mxc_env_pdf_u0028_vf3_u003b(d_3: ptr<function, vec3<f32>>) -> f32 {
    var param_68: vec3<f32>;

    let _e155 = (*d_3);
    param_68 = _e155;
    let _e156 = mxc_env_cell_u0028_vf3_u003b((&param_68));
    let _e160 = unnamed.mxc_env_cells[_e156][2u];
    return _e160;
}

fn mxc_env_to_map_u0028_vf3_u003b_f1_u003b(w: ptr<function, vec3<f32>>, angle_1: ptr<function, f32>) -> vec3<f32> {
    var c_4: f32;
    var s_4: f32;

    let _e157 = (*angle_1);
    c_4 = cos(_e157);
    let _e159 = (*angle_1);
    s_4 = sin(_e159);
    let _e161 = c_4;
    let _e163 = (*w)[0u];
    let _e165 = s_4;
    let _e167 = (*w)[2u];
    let _e171 = (*w)[1u];
    let _e172 = s_4;
    let _e174 = (*w)[0u];
    let _e176 = c_4;
    let _e178 = (*w)[2u];
    return vec3<f32>(((_e161 * _e163) - (_e165 * _e167)), _e171, ((_e172 * _e174) + (_e176 * _e178)));
}

fn mxc_env_lookup_u0028_vf3_u003b(d_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_69: vec3<f32>;

    let _e155 = (*d_4);
    param_69 = _e155;
    let _e156 = mxc_env_uv_u0028_vf3_u003b((&param_69));
    let _e157 = textureSampleLevel(mxc_env_radiance_texture, mxc_env_radiance_sampler, _e156, 0f);
    return _e157.xyz;
}

fn mxc_sky_u0028_vf3_u003b(d_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var y_1: f32;
    var horizon: vec3<f32>;
    var zenith: vec3<f32>;
    var ground: vec3<f32>;

    let _e159 = (*d_5)[1u];
    y_1 = clamp(_e159, -1f, 1f);
    horizon = vec3<f32>(1f, 0.96f, 0.9f);
    zenith = vec3<f32>(0.3f, 0.5f, 0.95f);
    ground = vec3<f32>(0.16f, 0.145f, 0.13f);
    let _e161 = y_1;
    if (_e161 >= 0f) {
        let _e163 = horizon;
        let _e164 = zenith;
        let _e165 = y_1;
        return mix(_e163, _e164, vec3(sqrt(_e165)));
    }
    let _e169 = horizon;
    let _e170 = ground;
    let _e171 = y_1;
    return mix(_e169, _e170, vec3(sqrt(-(_e171))));
}

fn mxc_environment_code_u0028_() -> i32 {
    var local_16: i32;

    if false {
        local_16 = MXC_ENVIRONMENT;
    } else {
        let _e156 = mxc_view.counts[1u];
        local_16 = _e156;
    }
    let _e157 = local_16;
    return _e157;
}

fn mxc_environment_u0028_vf3_u003b(d_6: ptr<function, vec3<f32>>) -> vec3<f32> {
    var code: i32;
    var param_70: vec3<f32>;
    var param_71: vec3<f32>;
    var param_72: f32;
    var param_73: vec3<f32>;

    let _e159 = mxc_environment_code_u0028_();
    code = _e159;
    let _e160 = code;
    if (_e160 == 1i) {
        let _e164 = mxc_view.environment[0u];
        return vec3(_e164);
    }
    let _e166 = code;
    if (_e166 == 2i) {
        let _e170 = mxc_view.environment[0u];
        let _e171 = (*d_6);
        param_70 = _e171;
        let _e172 = mxc_sky_u0028_vf3_u003b((&param_70));
        return (_e172 * _e170);
    }
    let _e174 = code;
    if (_e174 == 3i) {
        let _e178 = mxc_view.environment[0u];
        let _e179 = (*d_6);
        param_71 = _e179;
        let _e182 = mxc_view.environment[2u];
        param_72 = _e182;
        let _e183 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_71), (&param_72));
        param_73 = _e183;
        let _e184 = mxc_env_lookup_u0028_vf3_u003b((&param_73));
        return (_e184 * _e178);
    }
    return vec3<f32>(0f, 0f, 0f);
}

fn mxc_exit_direction_u0028_vf3_u003b_vf3_u003b(d_7: ptr<function, vec3<f32>>, t_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var axis: vec3<f32>;
    var s_5: f32;
    var c_5: f32;

    let _e158 = (*d_7);
    let _e159 = (*t_2);
    axis = cross(_e158, _e159);
    let _e161 = axis;
    s_5 = length(_e161);
    let _e163 = s_5;
    if (_e163 < 0.000001f) {
        let _e165 = (*t_2);
        return _e165;
    }
    let _e166 = s_5;
    let _e167 = axis;
    axis = (_e167 / vec3(_e166));
    let _e170 = (*d_7);
    let _e171 = (*t_2);
    c_5 = dot(_e170, _e171);
    let _e173 = (*t_2);
    let _e174 = c_5;
    let _e176 = axis;
    let _e177 = (*t_2);
    let _e179 = s_5;
    let _e182 = axis;
    let _e183 = axis;
    let _e184 = (*t_2);
    let _e187 = c_5;
    return (((_e173 * _e174) + (cross(_e176, _e177) * _e179)) + ((_e182 * dot(_e183, _e184)) * (1f - _e187)));
}

fn mxc_to_world_u0028_mf33_u003b_vf3_u003b(frame_2: ptr<function, mat3x3<f32>>, v_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e156 = (*frame_2)[0];
    let _e158 = (*v_4)[0u];
    let _e161 = (*frame_2)[1];
    let _e163 = (*v_4)[1u];
    let _e167 = (*frame_2)[2];
    let _e169 = (*v_4)[2u];
    return (((_e156 * _e158) + (_e161 * _e163)) + (_e167 * _e169));
}

fn mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b(wo_7: ptr<function, vec3<f32>>, alpha_7: ptr<function, vec2<f32>>, u_2: ptr<function, vec2<f32>>) -> vec3<f32> {
    var param_74: vec2<f32>;
    var vh: vec3<f32>;
    var lensq: f32;
    var t1_: vec3<f32>;
    var local_17: vec3<f32>;
    var t2_: vec3<f32>;
    var r_1: f32;
    var phi_1: f32;
    var p1_: f32;
    var p2_: f32;
    var s_6: f32;
    var param_75: f32;
    var nh: vec3<f32>;
    var param_76: f32;

    let _e170 = (*alpha_7);
    param_74 = _e170;
    let _e171 = mxc_rough_alpha_u0028_vf2_u003b((&param_74));
    (*alpha_7) = _e171;
    let _e173 = (*alpha_7)[0u];
    let _e175 = (*wo_7)[0u];
    let _e178 = (*alpha_7)[1u];
    let _e180 = (*wo_7)[1u];
    let _e183 = (*wo_7)[2u];
    vh = normalize(vec3<f32>((_e173 * _e175), (_e178 * _e180), _e183));
    let _e187 = vh[0u];
    let _e189 = vh[0u];
    let _e192 = vh[1u];
    let _e194 = vh[1u];
    lensq = ((_e187 * _e189) + (_e192 * _e194));
    let _e197 = lensq;
    if (_e197 > 0f) {
        let _e200 = vh[1u];
        let _e203 = vh[0u];
        let _e205 = lensq;
        local_17 = (vec3<f32>(-(_e200), _e203, 0f) * inverseSqrt(_e205));
    } else {
        local_17 = vec3<f32>(1f, 0f, 0f);
    }
    let _e208 = local_17;
    t1_ = _e208;
    let _e209 = vh;
    let _e210 = t1_;
    t2_ = cross(_e209, _e210);
    let _e213 = (*u_2)[0u];
    r_1 = sqrt(_e213);
    let _e216 = (*u_2)[1u];
    phi_1 = (6.2831855f * _e216);
    let _e218 = r_1;
    let _e219 = phi_1;
    p1_ = (_e218 * cos(_e219));
    let _e222 = r_1;
    let _e223 = phi_1;
    p2_ = (_e222 * sin(_e223));
    let _e227 = vh[2u];
    s_6 = (0.5f * (1f + _e227));
    let _e230 = s_6;
    let _e232 = p1_;
    let _e233 = p1_;
    param_75 = (1f - (_e232 * _e233));
    let _e236 = mxc_safe_sqrt_u0028_f1_u003b((&param_75));
    let _e238 = s_6;
    let _e239 = p2_;
    p2_ = (((1f - _e230) * _e236) + (_e238 * _e239));
    let _e242 = p1_;
    let _e243 = t1_;
    let _e245 = p2_;
    let _e246 = t2_;
    let _e249 = p1_;
    let _e250 = p1_;
    let _e253 = p2_;
    let _e254 = p2_;
    param_76 = ((1f - (_e249 * _e250)) - (_e253 * _e254));
    let _e257 = mxc_safe_sqrt_u0028_f1_u003b((&param_76));
    let _e258 = vh;
    nh = (((_e243 * _e242) + (_e246 * _e245)) + (_e258 * _e257));
    let _e262 = (*alpha_7)[0u];
    let _e264 = nh[0u];
    let _e267 = (*alpha_7)[1u];
    let _e269 = nh[1u];
    let _e272 = nh[2u];
    return normalize(vec3<f32>((_e262 * _e264), (_e267 * _e269), max(_e272, 0f)));
}

fn mxc_sample_cosine_u0028_vf2_u003b(u_3: ptr<function, vec2<f32>>) -> vec3<f32> {
    var r_2: f32;
    var phi_2: f32;
    var param_77: f32;

    let _e158 = (*u_3)[0u];
    r_2 = sqrt(_e158);
    let _e161 = (*u_3)[1u];
    phi_2 = (6.2831855f * _e161);
    let _e163 = r_2;
    let _e164 = phi_2;
    let _e167 = r_2;
    let _e168 = phi_2;
    let _e172 = (*u_3)[0u];
    param_77 = (1f - _e172);
    let _e174 = mxc_safe_sqrt_u0028_f1_u003b((&param_77));
    return vec3<f32>((_e163 * cos(_e164)), (_e167 * sin(_e168)), _e174);
}

fn mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_10: ptr<function, MxcLobe>, wo_8: ptr<function, vec3<f32>>, u_4: ptr<function, vec3<f32>>) -> MxcLobeSample {
    var s_7: MxcLobeSample;
    var above_3: bool;
    var o_2: vec3<f32>;
    var local_18: vec3<f32>;
    var delta: bool;
    var param_78: vec2<f32>;
    var m_6: vec3<f32>;
    var local_19: vec3<f32>;
    var param_79: vec3<f32>;
    var param_80: vec2<f32>;
    var param_81: vec2<f32>;
    var hm: f32;
    var transmits: bool;
    var param_82: MxcLobe;
    var reflects: bool;
    var f_3: vec3<f32>;
    var param_83: MxcLobe;
    var param_84: f32;
    var param_85: bool;
    var fr_1: f32;
    var local_20: f32;
    var param_86: vec3<f32>;
    var pReflect: f32;
    var local_21: f32;
    var i_4: vec3<f32>;
    var local_22: vec3<f32>;
    var tint: vec3<f32>;
    var local_23: vec3<f32>;
    var local_24: vec3<f32>;
    var param_87: MxcLobe;
    var param_88: vec3<f32>;
    var param_89: vec3<f32>;
    var param_90: MxcLobe;
    var param_91: vec3<f32>;
    var param_92: vec3<f32>;
    var param_93: vec2<f32>;
    var param_94: MxcLobe;
    var param_95: vec3<f32>;
    var param_96: vec3<f32>;
    var param_97: MxcLobe;
    var param_98: vec3<f32>;
    var param_99: vec3<f32>;
    var phi_3106_: bool;
    var phi_3111_: bool;
    var phi_3122_: bool;

    s_7.valid = false;
    s_7.delta = false;
    s_7.pdf = 0f;
    s_7.value = vec3<f32>(0f, 0f, 0f);
    s_7.wi = vec3<f32>(0f, 0f, 1f);
    let _e204 = (*l_10).kind;
    switch _e204 {
        case 2, 3, 1: {
            let _e231 = (*wo_8)[2u];
            above_3 = (_e231 > 0f);
            let _e233 = above_3;
            if _e233 {
                let _e234 = (*wo_8);
                local_18 = _e234;
            } else {
                let _e235 = (*wo_8);
                local_18 = -(_e235);
            }
            let _e237 = local_18;
            o_2 = _e237;
            let _e239 = o_2[2u];
            if (_e239 <= 0f) {
                let _e241 = s_7;
                return _e241;
            }
            let _e243 = (*l_10).alpha;
            param_78 = _e243;
            let _e244 = mxc_is_delta_u0028_vf2_u003b((&param_78));
            delta = _e244;
            let _e245 = delta;
            if _e245 {
                local_19 = vec3<f32>(0f, 0f, 1f);
            } else {
                let _e246 = o_2;
                param_79 = _e246;
                let _e248 = (*l_10).alpha;
                param_80 = _e248;
                let _e249 = (*u_4);
                param_81 = _e249.xy;
                let _e251 = mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b((&param_79), (&param_80), (&param_81));
                local_19 = _e251;
            }
            let _e252 = local_19;
            m_6 = _e252;
            let _e253 = o_2;
            let _e254 = m_6;
            hm = dot(_e253, _e254);
            let _e257 = (*l_10).kind;
            let _e258 = (_e257 == 1i);
            phi_3106_ = _e258;
            if !(_e258) {
                let _e261 = (*l_10).kind;
                phi_3106_ = (_e261 == 3i);
            }
            let _e264 = phi_3106_;
            phi_3111_ = _e264;
            if _e264 {
                let _e265 = (*l_10);
                param_82 = _e265;
                let _e266 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_82));
                phi_3111_ = _e266;
            }
            let _e268 = phi_3111_;
            transmits = _e268;
            let _e270 = (*l_10).kind;
            let _e271 = (_e270 == 2i);
            phi_3122_ = _e271;
            if !(_e271) {
                let _e274 = (*l_10).mode;
                phi_3122_ = ((_e274 & 1i) != 0i);
            }
            let _e278 = phi_3122_;
            reflects = _e278;
            let _e279 = hm;
            let _e281 = (*l_10);
            param_83 = _e281;
            param_84 = max(_e279, 0f);
            let _e282 = above_3;
            param_85 = _e282;
            let _e283 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_83), (&param_84), (&param_85));
            f_3 = _e283;
            let _e284 = transmits;
            if _e284 {
                let _e285 = f_3;
                param_86 = _e285;
                let _e286 = mxc_mean_u0028_vf3_u003b((&param_86));
                local_20 = _e286;
            } else {
                local_20 = 1f;
            }
            let _e287 = local_20;
            fr_1 = _e287;
            let _e288 = transmits;
            if _e288 {
                let _e289 = reflects;
                let _e290 = fr_1;
                local_21 = select(0f, _e290, _e289);
            } else {
                local_21 = 1f;
            }
            let _e292 = local_21;
            pReflect = _e292;
            let _e294 = (*u_4)[2u];
            let _e295 = pReflect;
            if (_e294 < _e295) {
                let _e297 = o_2;
                let _e299 = m_6;
                i_4 = reflect(-(_e297), _e299);
                let _e302 = i_4[2u];
                if (_e302 <= 0f) {
                    let _e304 = s_7;
                    return _e304;
                }
                let _e305 = above_3;
                if _e305 {
                    let _e306 = i_4;
                    local_22 = _e306;
                } else {
                    let _e307 = i_4;
                    local_22 = -(_e307);
                }
                let _e309 = local_22;
                s_7.wi = _e309;
                let _e311 = delta;
                s_7.delta = _e311;
                let _e313 = delta;
                if _e313 {
                    let _e315 = (*l_10).kind;
                    if (_e315 == 1i) {
                        let _e317 = above_3;
                        if _e317 {
                            let _e319 = (*l_10).c0_;
                            local_24 = _e319;
                        } else {
                            local_24 = vec3<f32>(1f, 1f, 1f);
                        }
                        let _e320 = local_24;
                        local_23 = _e320;
                    } else {
                        local_23 = vec3<f32>(1f, 1f, 1f);
                    }
                    let _e321 = local_23;
                    tint = _e321;
                    let _e322 = f_3;
                    let _e323 = tint;
                    s_7.value = (_e322 * _e323);
                    let _e326 = pReflect;
                    s_7.pdf = _e326;
                } else {
                    let _e328 = (*l_10);
                    param_87 = _e328;
                    let _e329 = (*wo_8);
                    param_88 = _e329;
                    let _e331 = s_7.wi;
                    param_89 = _e331;
                    let _e332 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_87), (&param_88), (&param_89));
                    s_7.value = _e332;
                    let _e334 = (*l_10);
                    param_90 = _e334;
                    let _e335 = (*wo_8);
                    param_91 = _e335;
                    let _e337 = s_7.wi;
                    param_92 = _e337;
                    let _e338 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_90), (&param_91), (&param_92));
                    s_7.pdf = _e338;
                }
                let _e341 = s_7.pdf;
                s_7.valid = (_e341 > 0f);
                let _e344 = s_7;
                return _e344;
            }
            let _e345 = s_7;
            return _e345;
        }
        default: {
            let _e206 = (*wo_8)[2u];
            if (_e206 <= 0f) {
                let _e208 = s_7;
                return _e208;
            }
            let _e209 = (*u_4);
            param_93 = _e209.xy;
            let _e211 = mxc_sample_cosine_u0028_vf2_u003b((&param_93));
            s_7.wi = _e211;
            let _e213 = (*l_10);
            param_94 = _e213;
            let _e214 = (*wo_8);
            param_95 = _e214;
            let _e216 = s_7.wi;
            param_96 = _e216;
            let _e217 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_94), (&param_95), (&param_96));
            s_7.value = _e217;
            let _e219 = (*l_10);
            param_97 = _e219;
            let _e220 = (*wo_8);
            param_98 = _e220;
            let _e222 = s_7.wi;
            param_99 = _e222;
            let _e223 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_97), (&param_98), (&param_99));
            s_7.pdf = _e223;
            let _e226 = s_7.pdf;
            s_7.valid = (_e226 > 0f);
            let _e229 = s_7;
            return _e229;
        }
    }
}

fn mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b(c_6: ptr<function, MxcClosure>, wo_9: ptr<function, vec3<f32>>, u_5: ptr<function, vec3<f32>>) -> MxcSample {
    var s_8: MxcSample;
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
    var param_100: vec3<f32>;
    var param_101: vec3<f32>;
    var o_3: vec3<f32>;
    var param_102: mat3x3<f32>;
    var param_103: vec3<f32>;
    var q: f32;
    var shaped_1: bool;
    var reflected: bool;
    var v_5: f32;
    var split: f32;
    var local_25: f32;
    var m_7: MxcLobe;
    var local_26: MxcLobe;
    var param_104: MxcLobe;
    var param_105: bool;
    var ls: MxcLobeSample;
    var param_106: MxcLobe;
    var param_107: vec3<f32>;
    var param_108: vec3<f32>;
    var param_109: mat3x3<f32>;
    var param_110: vec3<f32>;
    var param_111: MxcLobe;
    var param_112: f32;

    s_8.valid = false;
    s_8.delta = false;
    s_8.evaluate = false;
    s_8.pdf = 0f;
    s_8.weight = vec3<f32>(0f, 0f, 0f);
    let _e197 = (*wo_9);
    s_8.wi = _e197;
    let _e200 = (*c_6).choiceTotal;
    total = _e200;
    let _e202 = (*c_6).count;
    let _e204 = total;
    if ((_e202 == 0i) || (_e204 <= 0f)) {
        let _e207 = s_8;
        return _e207;
    }
    let _e209 = (*u_5)[2u];
    let _e210 = total;
    x_2 = (_e209 * _e210);
    chosen = -1i;
    before = 0f;
    p_2 = 0f;
    lastBefore = 0f;
    last = -1i;
    k_2 = 0i;
    loop {
        let _e212 = k_2;
        let _e214 = (*c_6).count;
        if (_e212 < _e214) {
            let _e216 = k_2;
            let _e219 = (*c_6).choice[_e216];
            pk_1 = _e219;
            let _e220 = pk_1;
            if (_e220 <= 0f) {
                continue;
            }
            let _e222 = x_2;
            let _e223 = before;
            let _e224 = pk_1;
            if (_e222 < (_e223 + _e224)) {
                let _e227 = k_2;
                chosen = _e227;
                let _e228 = pk_1;
                p_2 = _e228;
                break;
            }
            let _e229 = k_2;
            last = _e229;
            let _e230 = before;
            lastBefore = _e230;
            let _e231 = pk_1;
            let _e232 = before;
            before = (_e232 + _e231);
            continue;
        } else {
            break;
        }
        continuing {
            let _e234 = k_2;
            k_2 = (_e234 + 1i);
        }
    }
    let _e236 = chosen;
    if (_e236 < 0i) {
        let _e238 = last;
        chosen = max(_e238, 0i);
        let _e240 = chosen;
        let _e243 = (*c_6).choice[_e240];
        p_2 = _e243;
        let _e244 = lastBefore;
        before = _e244;
    }
    let _e245 = p_2;
    if (_e245 <= 0f) {
        let _e247 = s_8;
        return _e247;
    }
    let _e248 = x_2;
    let _e249 = before;
    let _e251 = p_2;
    uz = clamp(((_e248 - _e249) / _e251), 0f, 0.99999994f);
    let _e254 = chosen;
    let _e257 = (*c_6).lobes[_e254];
    l_11 = _e257;
    let _e259 = l_11.N;
    param_100 = _e259;
    let _e261 = l_11.T;
    param_101 = _e261;
    let _e262 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_100), (&param_101));
    frame_3 = _e262;
    let _e263 = frame_3;
    param_102 = _e263;
    let _e264 = (*wo_9);
    param_103 = _e264;
    let _e265 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_102), (&param_103));
    o_3 = _e265;
    let _e266 = chosen;
    let _e269 = (*c_6).msPick[_e266];
    q = _e269;
    let _e270 = uz;
    let _e271 = q;
    shaped_1 = (_e270 < _e271);
    reflected = true;
    let _e273 = shaped_1;
    if _e273 {
        let _e274 = uz;
        let _e275 = q;
        v_5 = (_e274 / _e275);
        let _e277 = chosen;
        let _e280 = (*c_6).msSplit[_e277];
        split = _e280;
        let _e281 = v_5;
        let _e282 = split;
        reflected = (_e281 < _e282);
        let _e284 = reflected;
        if _e284 {
            let _e285 = v_5;
            let _e286 = split;
            local_25 = (_e285 / max(_e286, 0.000001f));
        } else {
            let _e289 = v_5;
            let _e290 = split;
            let _e292 = split;
            local_25 = ((_e289 - _e290) / max((1f - _e292), 0.000001f));
        }
        let _e296 = local_25;
        uz = _e296;
    } else {
        let _e297 = uz;
        let _e298 = q;
        let _e300 = q;
        uz = ((_e297 - _e298) / (1f - _e300));
    }
    let _e303 = shaped_1;
    if _e303 {
        let _e304 = reflected;
        let _e306 = l_11;
        param_104 = _e306;
        param_105 = !(_e304);
        let _e307 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_104), (&param_105));
        local_26 = _e307;
    } else {
        let _e308 = l_11;
        local_26 = _e308;
    }
    let _e309 = local_26;
    m_7 = _e309;
    let _e310 = (*u_5);
    let _e311 = _e310.xy;
    let _e312 = uz;
    let _e317 = m_7;
    param_106 = _e317;
    let _e318 = o_3;
    param_107 = _e318;
    param_108 = vec3<f32>(_e311.x, _e311.y, min(_e312, 0.99999994f));
    let _e319 = mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_106), (&param_107), (&param_108));
    ls = _e319;
    let _e321 = ls.valid;
    if !(_e321) {
        let _e323 = s_8;
        return _e323;
    }
    let _e324 = frame_3;
    param_109 = _e324;
    let _e326 = ls.wi;
    param_110 = _e326;
    let _e327 = mxc_to_world_u0028_mf33_u003b_vf3_u003b((&param_109), (&param_110));
    s_8.wi = _e327;
    let _e330 = ls.delta;
    if _e330 {
        s_8.delta = true;
        let _e333 = ls.pdf;
        let _e334 = p_2;
        let _e336 = total;
        s_8.pdf = ((_e333 * _e334) / _e336);
        let _e340 = l_11.weight;
        let _e341 = chosen;
        let _e344 = (*c_6).ms[_e341];
        let _e348 = ls.wi[2u];
        let _e350 = l_11;
        param_111 = _e350;
        param_112 = abs(_e348);
        let _e351 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_111), (&param_112));
        let _e354 = ls.value;
        let _e357 = s_8.pdf;
        s_8.weight = ((((_e340 * _e344) * _e351) * _e354) / vec3(_e357));
        let _e362 = s_8.pdf;
        s_8.valid = (_e362 > 0f);
        let _e365 = s_8;
        return _e365;
    }
    s_8.evaluate = true;
    s_8.valid = true;
    let _e368 = s_8;
    return _e368;
}

fn mxc_radical_inverse_u0028_u1_u003b_u1_u003b(i_5: ptr<function, u32>, base: ptr<function, u32>) -> f32 {
    var inv: f32;
    var f_4: f32;
    var r_3: f32;

    let _e158 = (*base);
    if (_e158 == 2u) {
        let _e160 = (*i_5);
        return (f32((reverseBits(_e160) >> bitcast<u32>(8i))) * 0.000000059604645f);
    }
    let _e166 = (*base);
    inv = (1f / f32(_e166));
    let _e169 = inv;
    f_4 = _e169;
    r_3 = 0f;
    loop {
        let _e170 = (*i_5);
        if (_e170 > 0u) {
            let _e172 = f_4;
            let _e173 = (*i_5);
            let _e174 = (*base);
            let _e178 = r_3;
            r_3 = (_e178 + (_e172 * f32((_e173 % _e174))));
            let _e180 = inv;
            let _e181 = f_4;
            f_4 = (_e181 * _e180);
            continue;
        } else {
            break;
        }
        continuing {
            let _e183 = (*base);
            let _e184 = (*i_5);
            (*i_5) = (_e184 / _e183);
        }
    }
    let _e186 = r_3;
    return min(_e186, 0.99999994f);
}

fn mxc_pcg_u0028_u1_u003b(v_6: ptr<function, u32>) -> u32 {
    var state: u32;
    var word: u32;

    let _e156 = (*v_6);
    state = ((_e156 * 747796405u) + 2891336453u);
    let _e159 = state;
    let _e160 = state;
    let _e166 = state;
    word = (((_e159 >> bitcast<u32>(((_e160 >> bitcast<u32>(28u)) + 4u))) ^ _e166) * 277803737u);
    let _e169 = word;
    let _e172 = word;
    return ((_e169 >> bitcast<u32>(22u)) ^ _e172);
}

fn mxc_uniform_u0028_u1_u003b(seed: ptr<function, u32>) -> f32 {
    var param_113: u32;

    let _e155 = (*seed);
    param_113 = _e155;
    let _e156 = mxc_pcg_u0028_u1_u003b((&param_113));
    (*seed) = _e156;
    let _e157 = (*seed);
    return (f32((_e157 >> bitcast<u32>(8i))) * 0.000000059604645f);
}

fn mxc_light_kinds_u0028_() -> i32 {
    return 7i;
}

fn mxc_light_count_u0028_() -> i32 {
    var local_27: i32;

    if false {
        local_27 = MXC_LIGHT_COUNT;
    } else {
        let _e156 = mxc_view.counts[0u];
        local_27 = _e156;
    }
    let _e157 = local_27;
    return min(_e157, 8i);
}

fn mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b(mu_2: ptr<function, f32>, x_3: ptr<function, f32>, firstRow: ptr<function, f32>) -> vec4<f32> {
    var t_3: vec2<f32>;

    let _e157 = (*mu_2);
    let _e160 = (*x_3);
    t_3 = ((vec2<f32>(sqrt(clamp(_e157, 0f, 1f)), clamp(_e160, 0f, 1f)) * 31f) + vec2(0.5f));
    let _e167 = t_3[0u];
    let _e169 = (*firstRow);
    let _e171 = t_3[1u];
    let _e175 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, vec2<f32>((_e167 / 32f), ((_e169 + _e171) / 2070f)), 0f);
    return _e175;
}

fn mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b(mu_3: ptr<function, f32>, alpha_8: ptr<function, f32>, e: ptr<function, f32>) -> vec4<f32> {
    var s_9: f32;
    var s0_: f32;
    var x_4: f32;
    var a_3: vec4<f32>;
    var param_114: f32;
    var param_115: f32;
    var param_116: f32;
    var b_2: vec4<f32>;
    var param_117: f32;
    var param_118: f32;
    var param_119: f32;

    let _e167 = (*e);
    s_9 = (sqrt(clamp((0.5f * (_e167 - 1f)), 0f, 1f)) * 31f);
    let _e173 = s_9;
    s0_ = min(floor(_e173), 30f);
    let _e176 = (*alpha_8);
    x_4 = sqrt(max(_e176, 0f));
    let _e179 = s0_;
    let _e182 = (*mu_3);
    param_114 = _e182;
    let _e183 = x_4;
    param_115 = _e183;
    param_116 = (32f * (1f + _e179));
    let _e184 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_114), (&param_115), (&param_116));
    a_3 = _e184;
    let _e185 = s0_;
    let _e188 = (*mu_3);
    param_117 = _e188;
    let _e189 = x_4;
    param_118 = _e189;
    param_119 = (32f * (2f + _e185));
    let _e190 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_117), (&param_118), (&param_119));
    b_2 = _e190;
    let _e191 = a_3;
    let _e192 = b_2;
    let _e193 = s_9;
    let _e194 = s0_;
    return mix(_e191, _e192, vec4((_e193 - _e194)));
}

fn mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b(mu_4: ptr<function, f32>, alpha_9: ptr<function, f32>, eta_1: ptr<function, f32>) -> f32 {
    var param_120: f32;
    var param_121: f32;
    var param_122: f32;
    var param_123: f32;
    var param_124: f32;
    var param_125: f32;

    let _e162 = (*eta_1);
    if (_e162 >= 1f) {
        let _e164 = (*mu_4);
        param_120 = _e164;
        let _e165 = (*alpha_9);
        param_121 = _e165;
        let _e166 = (*eta_1);
        param_122 = _e166;
        let _e167 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_120), (&param_121), (&param_122));
        return _e167.y;
    }
    let _e169 = (*eta_1);
    let _e172 = (*mu_4);
    param_123 = _e172;
    let _e173 = (*alpha_9);
    param_124 = _e173;
    param_125 = (1f / max(_e169, 0.001f));
    let _e174 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_123), (&param_124), (&param_125));
    return _e174.z;
}

fn mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b(mu_5: ptr<function, f32>, alpha_10: ptr<function, f32>, eta_2: ptr<function, f32>) -> f32 {
    var e_1: f32;
    var local_28: f32;
    var param_126: f32;
    var param_127: f32;
    var param_128: f32;

    let _e161 = (*eta_2);
    if (_e161 >= 1f) {
        let _e163 = (*eta_2);
        local_28 = _e163;
    } else {
        let _e164 = (*eta_2);
        local_28 = (1f / max(_e164, 0.001f));
    }
    let _e167 = local_28;
    e_1 = _e167;
    let _e168 = (*mu_5);
    param_126 = _e168;
    let _e169 = (*alpha_10);
    param_127 = _e169;
    let _e170 = e_1;
    param_128 = _e170;
    let _e171 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_126), (&param_127), (&param_128));
    return _e171.x;
}

fn mxc_fon_albedo_u0028_f1_u003b_f1_u003b(sigma_1: ptr<function, f32>, mu_6: ptr<function, f32>) -> f32 {
    var a_4: f32;
    var c_7: f32;
    var s_10: f32;
    var param_129: f32;
    var theta: f32;
    var tail: f32;
    var local_29: f32;
    var g: f32;

    let _e163 = (*sigma_1);
    a_4 = (1f / (1f + (0.2877934f * _e163)));
    let _e167 = (*mu_6);
    c_7 = clamp(_e167, 0f, 1f);
    let _e169 = c_7;
    let _e170 = c_7;
    param_129 = (1f - (_e169 * _e170));
    let _e173 = mxc_safe_sqrt_u0028_f1_u003b((&param_129));
    s_10 = _e173;
    let _e174 = c_7;
    theta = acos(_e174);
    let _e176 = c_7;
    if (_e176 > 0.0001f) {
        let _e178 = s_10;
        let _e179 = s_10;
        let _e181 = s_10;
        let _e184 = c_7;
        local_29 = ((1f - ((_e178 * _e179) * _e181)) / _e184);
    } else {
        let _e186 = c_7;
        local_29 = (1.5f * _e186);
    }
    let _e188 = local_29;
    tail = _e188;
    let _e189 = s_10;
    let _e190 = theta;
    let _e191 = s_10;
    let _e192 = c_7;
    let _e196 = s_10;
    let _e198 = tail;
    let _e201 = s_10;
    g = (((_e189 * (_e190 - (_e191 * _e192))) + ((0.6666667f * _e196) * _e198)) - (0.6666667f * _e201));
    let _e204 = a_4;
    let _e205 = (*sigma_1);
    let _e206 = a_4;
    let _e208 = g;
    return (_e204 + (((_e205 * _e206) * _e208) * 0.31830987f));
}

fn mxc_table_u0028_f1_u003b_f1_u003b(mu_7: ptr<function, f32>, x_5: ptr<function, f32>) -> vec4<f32> {
    var param_130: f32;
    var param_131: f32;
    var param_132: f32;

    let _e158 = (*mu_7);
    param_130 = _e158;
    let _e159 = (*x_5);
    param_131 = _e159;
    param_132 = 0f;
    let _e160 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_130), (&param_131), (&param_132));
    return _e160;
}

fn mxc_split_sum_u0028_f1_u003b_f1_u003b(mu_8: ptr<function, f32>, alpha_11: ptr<function, f32>) -> vec2<f32> {
    var param_133: f32;
    var param_134: f32;

    let _e157 = (*alpha_11);
    let _e160 = (*mu_8);
    param_133 = _e160;
    param_134 = sqrt(max(_e157, 0f));
    let _e161 = mxc_table_u0028_f1_u003b_f1_u003b((&param_133), (&param_134));
    return _e161.xy;
}

fn mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_12: ptr<function, MxcLobe>, wo_10: ptr<function, vec3<f32>>, ms: ptr<function, vec3<f32>>) -> vec3<f32> {
    var mu_9: f32;
    var alpha_12: f32;
    var param_135: vec2<f32>;
    var e_2: vec3<f32>;
    var param_136: MxcLobe;
    var param_137: f32;
    var param_138: f32;
    var param_139: f32;
    var param_140: f32;
    var ab: vec2<f32>;
    var param_141: f32;
    var param_142: f32;
    var f0_: vec3<f32>;
    var param_143: MxcLobe;
    var param_144: f32;
    var param_145: bool;
    var f90_: vec3<f32>;
    var param_146: MxcLobe;
    var param_147: f32;
    var param_148: bool;
    var tint_1: vec3<f32>;
    var local_30: vec3<f32>;
    var param_149: vec2<f32>;
    var param_150: MxcLobe;
    var param_151: f32;
    var param_152: bool;
    var param_153: f32;
    var param_154: f32;
    var phi_2605_: bool;
    var phi_2612_: bool;
    var phi_2630_: bool;

    let _e185 = (*wo_10)[2u];
    mu_9 = clamp(_e185, 0f, 1f);
    let _e188 = (*l_12).kind;
    let _e189 = (_e188 == 1i);
    phi_2605_ = _e189;
    if !(_e189) {
        let _e192 = (*l_12).kind;
        phi_2605_ = (_e192 == 2i);
    }
    let _e195 = phi_2605_;
    phi_2612_ = _e195;
    if !(_e195) {
        let _e198 = (*l_12).kind;
        phi_2612_ = (_e198 == 3i);
    }
    let _e201 = phi_2612_;
    if _e201 {
        let _e204 = (*l_12).alpha[0u];
        let _e207 = (*l_12).alpha[1u];
        alpha_12 = sqrt((_e204 * _e207));
        let _e211 = (*l_12).kind;
        let _e212 = (_e211 == 1i);
        phi_2630_ = _e212;
        if _e212 {
            let _e214 = (*l_12).alpha;
            param_135 = _e214;
            let _e215 = mxc_is_delta_u0028_vf2_u003b((&param_135));
            phi_2630_ = !(_e215);
        }
        let _e218 = phi_2630_;
        if _e218 {
            let _e219 = (*l_12);
            param_136 = _e219;
            let _e220 = mu_9;
            param_137 = _e220;
            let _e221 = mxc_lobe_cosine_below_coat_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_136), (&param_137));
            param_138 = _e221;
            let _e222 = alpha_12;
            param_139 = _e222;
            let _e224 = (*l_12).eta;
            param_140 = _e224;
            let _e225 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_138), (&param_139), (&param_140));
            e_2 = vec3(_e225);
            let _e227 = e_2;
            let _e229 = (*l_12).c0_;
            let _e231 = (*ms);
            return clamp(((_e227 * _e229) * _e231), vec3(0f), vec3(1f));
        }
        let _e236 = mu_9;
        param_141 = _e236;
        let _e237 = alpha_12;
        param_142 = _e237;
        let _e238 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_141), (&param_142));
        ab = _e238;
        let _e239 = (*l_12);
        param_143 = _e239;
        param_144 = 1f;
        param_145 = true;
        let _e240 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_143), (&param_144), (&param_145));
        f0_ = _e240;
        let _e241 = (*l_12);
        param_146 = _e241;
        param_147 = 0f;
        param_148 = true;
        let _e242 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_146), (&param_147), (&param_148));
        f90_ = _e242;
        let _e244 = (*l_12).kind;
        if (_e244 == 1i) {
            let _e247 = (*l_12).c0_;
            local_30 = _e247;
        } else {
            local_30 = vec3<f32>(1f, 1f, 1f);
        }
        let _e248 = local_30;
        tint_1 = _e248;
        let _e250 = (*l_12).alpha;
        param_149 = _e250;
        let _e251 = mxc_is_delta_u0028_vf2_u003b((&param_149));
        if _e251 {
            let _e252 = (*l_12);
            param_150 = _e252;
            let _e253 = mu_9;
            param_151 = _e253;
            param_152 = true;
            let _e254 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_150), (&param_151), (&param_152));
            let _e255 = tint_1;
            return (_e254 * _e255);
        }
        let _e257 = f0_;
        let _e259 = ab[0u];
        let _e261 = f90_;
        let _e263 = ab[1u];
        let _e266 = tint_1;
        let _e268 = (*ms);
        return clamp(((((_e257 * _e259) + (_e261 * _e263)) * _e266) * _e268), vec3(0f), vec3(1f));
    }
    let _e274 = (*l_12).kind;
    if (_e274 == 4i) {
        let _e277 = (*l_12).c0_;
        let _e279 = (*l_12).p0_;
        param_153 = _e279;
        let _e280 = mu_9;
        param_154 = _e280;
        let _e281 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_153), (&param_154));
        return (_e277 * _e281);
    }
    let _e284 = (*l_12).kind;
    if (_e284 == 8i) {
        let _e287 = (*l_12).c0_;
        return _e287;
    }
    let _e289 = (*l_12).c0_;
    return _e289;
}

fn mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_13: ptr<function, MxcLobe>, wo_11: ptr<function, vec3<f32>>) -> bool {
    var phi_2227_: bool;

    let _e156 = (*wo_11)[2u];
    let _e157 = (_e156 <= 0f);
    phi_2227_ = _e157;
    if !(_e157) {
        let _e160 = (*l_13).eta;
        phi_2227_ = (_e160 < 1f);
    }
    let _e163 = phi_2227_;
    if _e163 {
        return false;
    }
    return true;
}

fn mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_14: ptr<function, MxcLobe>) -> bool {
    let _e155 = (*l_14).eta;
    return (abs((_e155 - 1f)) < 0.0001f);
}

fn mxc_lobe_ms_shaped_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_15: ptr<function, MxcLobe>, wo_12: ptr<function, vec3<f32>>) -> bool {
    var param_155: vec2<f32>;
    var param_156: MxcLobe;
    var param_157: MxcLobe;
    var param_158: vec3<f32>;
    var phi_2480_: bool;
    var phi_2506_: bool;
    var phi_2513_: bool;
    var phi_2519_: bool;
    var phi_2525_: bool;

    let _e160 = (*wo_12)[2u];
    let _e161 = (_e160 <= 0f);
    phi_2480_ = _e161;
    if !(_e161) {
        let _e164 = (*l_15).alpha;
        param_155 = _e164;
        let _e165 = mxc_is_delta_u0028_vf2_u003b((&param_155));
        phi_2480_ = _e165;
    }
    let _e167 = phi_2480_;
    if _e167 {
        return false;
    }
    let _e169 = (*l_15).kind;
    if (_e169 == 2i) {
        return true;
    }
    let _e172 = (*l_15).kind;
    if (_e172 == 3i) {
        let _e175 = (*l_15).mode;
        return ((_e175 & 1i) != 0i);
    }
    let _e179 = (*l_15).kind;
    let _e180 = (_e179 == 1i);
    phi_2506_ = _e180;
    if _e180 {
        let _e182 = (*l_15).mode;
        phi_2506_ = ((_e182 & 1i) != 0i);
    }
    let _e186 = phi_2506_;
    phi_2513_ = _e186;
    if _e186 {
        let _e188 = (*l_15).mode;
        phi_2513_ = ((_e188 & 4i) == 0i);
    }
    let _e192 = phi_2513_;
    phi_2519_ = _e192;
    if _e192 {
        let _e193 = (*l_15);
        param_156 = _e193;
        let _e194 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_156));
        phi_2519_ = !(_e194);
    }
    let _e197 = phi_2519_;
    phi_2525_ = _e197;
    if _e197 {
        let _e198 = (*l_15);
        param_157 = _e198;
        let _e199 = (*wo_12);
        param_158 = _e199;
        let _e200 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_157), (&param_158));
        phi_2525_ = _e200;
    }
    let _e202 = phi_2525_;
    return _e202;
}

fn mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_16: ptr<function, MxcLobe>, woLocal: ptr<function, vec3<f32>>, ms_1: ptr<function, vec3<f32>>) -> f32 {
    var param_159: MxcLobe;
    var param_160: vec3<f32>;
    var param_161: vec3<f32>;
    var param_162: vec3<f32>;

    let _e161 = (*l_16).weight;
    if all((_e161 == vec3<f32>(0f, 0f, 0f))) {
        return 0f;
    }
    let _e165 = (*l_16).weight;
    let _e166 = (*l_16);
    param_159 = _e166;
    let _e167 = (*woLocal);
    param_160 = _e167;
    let _e168 = (*ms_1);
    param_161 = _e168;
    let _e169 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_159), (&param_160), (&param_161));
    param_162 = (_e165 * _e169);
    let _e171 = mxc_luminance_u0028_vf3_u003b((&param_162));
    return (max(_e171, 0f) + 0.0001f);
}

fn mxc_walk_texel_u0028_f1_u003b_f1_u003b(column: ptr<function, f32>, row: ptr<function, f32>) -> f32 {
    var t_4: vec2<f32>;

    let _e156 = (*column);
    let _e158 = (*row);
    t_4 = (vec2<f32>((_e156 + 0.5f), (_e158 + 0.5f)) / vec2<f32>(32f, 2070f));
    let _e162 = t_4;
    let _e163 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, _e162, 0f);
    return _e163.x;
}

fn mxc_walk_eta_index_u0028_f1_u003b(eta_3: ptr<function, f32>) -> f32 {
    var e_3: f32;

    let _e155 = (*eta_3);
    e_3 = max(_e155, 1f);
    let _e157 = e_3;
    let _e160 = e_3;
    return (clamp(((2f * (_e157 - 1f)) / (_e160 + 1f)), 0f, 1f) * 12f);
}

fn mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b(mu_10: ptr<function, f32>, alpha_13: ptr<function, f32>, eta_4: ptr<function, f32>) -> f32 {
    var fe: f32;
    var param_163: f32;
    var e0_: f32;
    var column_1: f32;
    var row_1: f32;
    var a_5: f32;
    var param_164: f32;
    var param_165: f32;
    var b_3: f32;
    var param_166: f32;
    var param_167: f32;

    let _e167 = (*eta_4);
    param_163 = _e167;
    let _e168 = mxc_walk_eta_index_u0028_f1_u003b((&param_163));
    fe = _e168;
    let _e169 = fe;
    e0_ = min(floor(_e169), 11f);
    let _e172 = (*mu_10);
    column_1 = (sqrt(clamp(_e172, 0f, 1f)) * 31f);
    let _e176 = (*alpha_13);
    row_1 = (1654f + (sqrt(clamp(_e176, 0f, 1f)) * 31f));
    let _e181 = row_1;
    let _e182 = e0_;
    let _e185 = column_1;
    param_164 = _e185;
    param_165 = (_e181 + (_e182 * 32f));
    let _e186 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_164), (&param_165));
    a_5 = _e186;
    let _e187 = row_1;
    let _e188 = e0_;
    let _e192 = column_1;
    param_166 = _e192;
    param_167 = (_e187 + ((_e188 + 1f) * 32f));
    let _e193 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_166), (&param_167));
    b_3 = _e193;
    let _e194 = a_5;
    let _e195 = b_3;
    let _e196 = fe;
    let _e197 = e0_;
    return mix(_e194, _e195, (_e196 - _e197));
}

fn mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_17: ptr<function, MxcLobe>, wo_13: ptr<function, vec3<f32>>, ms_2: ptr<function, vec3<f32>>) -> f32 {
    var param_168: vec2<f32>;
    var param_169: MxcLobe;
    var param_170: MxcLobe;
    var param_171: vec3<f32>;
    var alpha_14: f32;
    var rss: f32;
    var param_172: f32;
    var param_173: f32;
    var param_174: f32;
    var tss: f32;
    var param_175: f32;
    var param_176: f32;
    var param_177: f32;
    var param_178: f32;
    var param_179: f32;
    var param_180: f32;
    var phi_2260_: bool;
    var phi_2266_: bool;
    var phi_2274_: bool;
    var phi_2282_: bool;

    let _e173 = (*l_17).kind;
    let _e174 = (_e173 != 1i);
    phi_2260_ = _e174;
    if !(_e174) {
        let _e177 = (*l_17).alpha;
        param_168 = _e177;
        let _e178 = mxc_is_delta_u0028_vf2_u003b((&param_168));
        phi_2260_ = _e178;
    }
    let _e180 = phi_2260_;
    phi_2266_ = _e180;
    if !(_e180) {
        let _e182 = (*l_17);
        param_169 = _e182;
        let _e183 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_169));
        phi_2266_ = _e183;
    }
    let _e185 = phi_2266_;
    phi_2274_ = _e185;
    if !(_e185) {
        let _e188 = (*l_17).mode;
        phi_2274_ = ((_e188 & 4i) != 0i);
    }
    let _e192 = phi_2274_;
    phi_2282_ = _e192;
    if !(_e192) {
        let _e194 = (*l_17);
        param_170 = _e194;
        let _e195 = (*wo_13);
        param_171 = _e195;
        let _e196 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_170), (&param_171));
        phi_2282_ = !(_e196);
    }
    let _e199 = phi_2282_;
    if _e199 {
        let _e201 = (*ms_2)[0u];
        return _e201;
    }
    let _e204 = (*l_17).alpha[0u];
    let _e207 = (*l_17).alpha[1u];
    alpha_14 = sqrt((_e204 * _e207));
    let _e211 = (*wo_13)[2u];
    param_172 = _e211;
    let _e212 = alpha_14;
    param_173 = _e212;
    let _e214 = (*l_17).eta;
    param_174 = _e214;
    let _e215 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_172), (&param_173), (&param_174));
    rss = _e215;
    let _e217 = (*wo_13)[2u];
    param_175 = _e217;
    let _e218 = alpha_14;
    param_176 = _e218;
    let _e220 = (*l_17).eta;
    param_177 = _e220;
    let _e221 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_175), (&param_176), (&param_177));
    let _e222 = rss;
    tss = (_e221 - _e222);
    let _e225 = (*wo_13)[2u];
    param_178 = _e225;
    let _e226 = alpha_14;
    param_179 = _e226;
    let _e228 = (*l_17).eta;
    param_180 = _e228;
    let _e229 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_178), (&param_179), (&param_180));
    let _e231 = tss;
    return clamp(((1f - _e229) / max(_e231, 0.05f)), 1f, 20f);
}

fn mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_18: ptr<function, MxcLobe>, wo_14: ptr<function, vec3<f32>>) -> vec3<f32> {
    var microfacet: bool;
    var param_181: vec2<f32>;
    var alpha_15: f32;
    var param_182: MxcLobe;
    var param_183: MxcLobe;
    var param_184: vec3<f32>;
    var rss_1: f32;
    var param_185: f32;
    var param_186: f32;
    var param_187: f32;
    var param_188: f32;
    var param_189: f32;
    var param_190: f32;
    var e_4: f32;
    var param_191: MxcLobe;
    var param_192: bool;
    var param_193: f32;
    var param_194: f32;
    var param_195: f32;
    var k_3: vec3<f32>;
    var ab_1: vec2<f32>;
    var param_196: f32;
    var param_197: f32;
    var e_5: f32;
    var param_198: MxcLobe;
    var param_199: f32;
    var param_200: bool;
    var phi_2358_: bool;
    var phi_2365_: bool;
    var phi_2374_: bool;
    var phi_2390_: bool;
    var phi_2402_: bool;

    let _e183 = (*l_18).kind;
    let _e184 = (_e183 == 1i);
    phi_2358_ = _e184;
    if !(_e184) {
        let _e187 = (*l_18).kind;
        phi_2358_ = (_e187 == 2i);
    }
    let _e190 = phi_2358_;
    phi_2365_ = _e190;
    if !(_e190) {
        let _e193 = (*l_18).kind;
        phi_2365_ = (_e193 == 3i);
    }
    let _e196 = phi_2365_;
    microfacet = _e196;
    let _e197 = microfacet;
    let _e198 = !(_e197);
    phi_2374_ = _e198;
    if !(_e198) {
        let _e201 = (*l_18).alpha;
        param_181 = _e201;
        let _e202 = mxc_is_delta_u0028_vf2_u003b((&param_181));
        phi_2374_ = _e202;
    }
    let _e204 = phi_2374_;
    if _e204 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e207 = (*l_18).alpha[0u];
    let _e210 = (*l_18).alpha[1u];
    alpha_15 = sqrt((_e207 * _e210));
    let _e214 = (*l_18).kind;
    let _e215 = (_e214 == 1i);
    phi_2390_ = _e215;
    if _e215 {
        let _e216 = (*l_18);
        param_182 = _e216;
        let _e217 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_182));
        phi_2390_ = _e217;
    }
    let _e219 = phi_2390_;
    if _e219 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e221 = (*l_18).kind;
    let _e222 = (_e221 == 1i);
    phi_2402_ = _e222;
    if _e222 {
        let _e224 = (*l_18).mode;
        phi_2402_ = ((_e224 & 4i) == 0i);
    }
    let _e228 = phi_2402_;
    if _e228 {
        let _e229 = (*l_18);
        param_183 = _e229;
        let _e230 = (*wo_14);
        param_184 = _e230;
        let _e231 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_183), (&param_184));
        if _e231 {
            let _e233 = (*wo_14)[2u];
            param_185 = _e233;
            let _e234 = alpha_15;
            param_186 = _e234;
            let _e236 = (*l_18).eta;
            param_187 = _e236;
            let _e237 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_185), (&param_186), (&param_187));
            rss_1 = _e237;
            let _e239 = (*wo_14)[2u];
            param_188 = _e239;
            let _e240 = alpha_15;
            param_189 = _e240;
            let _e242 = (*l_18).eta;
            param_190 = _e242;
            let _e243 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_188), (&param_189), (&param_190));
            let _e244 = rss_1;
            return vec3(clamp((_e243 / max(_e244, 0.0001f)), 1f, 20f));
        }
        let _e250 = (*wo_14)[2u];
        let _e253 = (*wo_14)[2u];
        let _e255 = (*l_18);
        param_191 = _e255;
        param_192 = (_e253 >= 0f);
        let _e256 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_191), (&param_192));
        param_193 = abs(_e250);
        let _e257 = alpha_15;
        param_194 = _e257;
        param_195 = _e256;
        let _e258 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_193), (&param_194), (&param_195));
        e_4 = _e258;
        let _e259 = e_4;
        k_3 = vec3((1f / max(_e259, 0.05f)));
        let _e263 = k_3;
        return _e263;
    }
    let _e265 = (*wo_14)[2u];
    param_196 = max(_e265, 0f);
    let _e267 = alpha_15;
    param_197 = _e267;
    let _e268 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_196), (&param_197));
    ab_1 = _e268;
    let _e270 = ab_1[0u];
    let _e272 = ab_1[1u];
    e_5 = (_e270 + _e272);
    let _e274 = (*l_18);
    param_198 = _e274;
    param_199 = 1f;
    param_200 = true;
    let _e275 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_198), (&param_199), (&param_200));
    let _e276 = e_5;
    let _e279 = e_5;
    return (vec3(1f) + ((_e275 * (1f - _e276)) / vec3(max(_e279, 0.05f))));
}

fn mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b(c_8: ptr<function, MxcClosure>, wo_15: ptr<function, vec3<f32>>) {
    var k_4: i32;
    var l_19: MxcLobe;
    var o_4: vec3<f32>;
    var param_201: vec3<f32>;
    var param_202: vec3<f32>;
    var param_203: mat3x3<f32>;
    var param_204: vec3<f32>;
    var ms_3: vec3<f32>;
    var param_205: MxcLobe;
    var param_206: vec3<f32>;
    var param_207: MxcLobe;
    var param_208: vec3<f32>;
    var param_209: vec3<f32>;
    var param_210: MxcLobe;
    var param_211: vec3<f32>;
    var param_212: vec3<f32>;
    var param_213: MxcLobe;
    var param_214: vec3<f32>;
    var alpha_16: f32;
    var reflected_1: vec3<f32>;
    var param_215: MxcLobe;
    var param_216: vec3<f32>;
    var param_217: vec3<f32>;
    var addedR: vec3<f32>;
    var param_218: MxcLobe;
    var param_219: vec3<f32>;
    var param_220: vec3<f32>;
    var transmitted_1: vec3<f32>;
    var addedT: vec3<f32>;
    var param_221: MxcLobe;
    var rss_2: f32;
    var param_222: f32;
    var param_223: f32;
    var param_224: f32;
    var param_225: f32;
    var param_226: f32;
    var param_227: f32;
    var mr: MxcLobe;
    var param_228: MxcLobe;
    var param_229: bool;
    var broadR: vec3<f32>;
    var param_230: MxcLobe;
    var param_231: vec3<f32>;
    var param_232: vec3<f32>;
    var broadT: f32;
    var param_233: MxcLobe;
    var mt: MxcLobe;
    var param_234: MxcLobe;
    var param_235: bool;
    var at: f32;
    var param_236: f32;
    var param_237: f32;
    var param_238: f32;
    var param_239: f32;
    var param_240: f32;
    var param_241: f32;
    var total_1: f32;
    var param_242: vec3<f32>;
    var added: f32;
    var param_243: vec3<f32>;
    var local_31: f32;
    var param_244: vec3<f32>;
    var phi_3400_: bool;
    var phi_3440_: bool;

    (*c_8).choiceTotal = 0f;
    k_4 = 0i;
    loop {
        let _e218 = k_4;
        let _e220 = (*c_8).count;
        if (_e218 < _e220) {
            let _e222 = k_4;
            let _e225 = (*c_8).lobes[_e222];
            l_19 = _e225;
            let _e226 = k_4;
            (*c_8).ms[_e226] = vec3<f32>(1f, 1f, 1f);
            let _e229 = k_4;
            (*c_8).msT[_e229] = 1f;
            let _e232 = k_4;
            (*c_8).msLobe[_e232] = vec3<f32>(0f, 0f, 0f);
            let _e235 = k_4;
            (*c_8).msLobeT[_e235] = vec3<f32>(0f, 0f, 0f);
            let _e238 = k_4;
            (*c_8).msPick[_e238] = 0f;
            let _e241 = k_4;
            (*c_8).msSplit[_e241] = 1f;
            let _e244 = k_4;
            (*c_8).choice[_e244] = 0f;
            let _e248 = l_19.weight;
            if all((_e248 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e252 = l_19.N;
            param_201 = _e252;
            let _e254 = l_19.T;
            param_202 = _e254;
            let _e255 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_201), (&param_202));
            param_203 = _e255;
            let _e256 = (*wo_15);
            param_204 = _e256;
            let _e257 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_203), (&param_204));
            o_4 = _e257;
            let _e258 = l_19;
            param_205 = _e258;
            let _e259 = o_4;
            param_206 = _e259;
            let _e260 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_205), (&param_206));
            ms_3 = _e260;
            let _e261 = k_4;
            let _e262 = l_19;
            param_207 = _e262;
            let _e263 = o_4;
            param_208 = _e263;
            let _e264 = ms_3;
            param_209 = _e264;
            let _e265 = mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_207), (&param_208), (&param_209));
            (*c_8).msT[_e261] = _e265;
            let _e268 = k_4;
            let _e269 = l_19;
            param_210 = _e269;
            let _e270 = o_4;
            param_211 = _e270;
            let _e271 = ms_3;
            param_212 = _e271;
            let _e272 = mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_210), (&param_211), (&param_212));
            (*c_8).choice[_e268] = _e272;
            let _e275 = k_4;
            let _e278 = (*c_8).choice[_e275];
            let _e280 = (*c_8).choiceTotal;
            (*c_8).choiceTotal = (_e280 + _e278);
            let _e283 = l_19;
            param_213 = _e283;
            let _e284 = o_4;
            param_214 = _e284;
            let _e285 = mxc_lobe_ms_shaped_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_213), (&param_214));
            if _e285 {
                let _e288 = l_19.alpha[0u];
                let _e291 = l_19.alpha[1u];
                alpha_16 = sqrt((_e288 * _e291));
                let _e294 = l_19;
                param_215 = _e294;
                let _e295 = o_4;
                param_216 = _e295;
                param_217 = vec3<f32>(1f, 1f, 1f);
                let _e296 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_215), (&param_216), (&param_217));
                reflected_1 = _e296;
                let _e297 = l_19;
                param_218 = _e297;
                let _e298 = o_4;
                param_219 = _e298;
                let _e299 = ms_3;
                param_220 = _e299;
                let _e300 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_218), (&param_219), (&param_220));
                let _e301 = reflected_1;
                addedR = max((_e300 - _e301), vec3<f32>(0f, 0f, 0f));
                transmitted_1 = vec3<f32>(0f, 0f, 0f);
                addedT = vec3<f32>(0f, 0f, 0f);
                let _e305 = l_19.kind;
                let _e306 = (_e305 == 1i);
                phi_3400_ = _e306;
                if _e306 {
                    let _e307 = l_19;
                    param_221 = _e307;
                    let _e308 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_221));
                    phi_3400_ = _e308;
                }
                let _e310 = phi_3400_;
                if _e310 {
                    let _e312 = o_4[2u];
                    param_222 = _e312;
                    let _e313 = alpha_16;
                    param_223 = _e313;
                    let _e315 = l_19.eta;
                    param_224 = _e315;
                    let _e316 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_222), (&param_223), (&param_224));
                    rss_2 = _e316;
                    let _e318 = o_4[2u];
                    param_225 = _e318;
                    let _e319 = alpha_16;
                    param_226 = _e319;
                    let _e321 = l_19.eta;
                    param_227 = _e321;
                    let _e322 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_225), (&param_226), (&param_227));
                    let _e323 = rss_2;
                    let _e327 = l_19.c1_;
                    transmitted_1 = (_e327 * max((_e322 - _e323), 0f));
                    let _e329 = k_4;
                    let _e332 = (*c_8).msT[_e329];
                    let _e335 = transmitted_1;
                    addedT = (_e335 * max((_e332 - 1f), 0f));
                }
                let _e337 = l_19;
                param_228 = _e337;
                param_229 = false;
                let _e338 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_228), (&param_229));
                mr = _e338;
                let _e339 = mr;
                param_230 = _e339;
                let _e340 = o_4;
                param_231 = _e340;
                param_232 = vec3<f32>(1f, 1f, 1f);
                let _e341 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_230), (&param_231), (&param_232));
                broadR = _e341;
                broadT = 1f;
                let _e343 = l_19.kind;
                let _e344 = (_e343 == 1i);
                phi_3440_ = _e344;
                if _e344 {
                    let _e345 = l_19;
                    param_233 = _e345;
                    let _e346 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_233));
                    phi_3440_ = _e346;
                }
                let _e348 = phi_3440_;
                if _e348 {
                    let _e349 = l_19;
                    param_234 = _e349;
                    param_235 = true;
                    let _e350 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_234), (&param_235));
                    mt = _e350;
                    let _e353 = mt.alpha[0u];
                    let _e356 = mt.alpha[1u];
                    at = sqrt((_e353 * _e356));
                    let _e360 = o_4[2u];
                    param_236 = _e360;
                    let _e361 = at;
                    param_237 = _e361;
                    let _e363 = l_19.eta;
                    param_238 = _e363;
                    let _e364 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_236), (&param_237), (&param_238));
                    let _e366 = o_4[2u];
                    param_239 = _e366;
                    let _e367 = at;
                    param_240 = _e367;
                    let _e369 = l_19.eta;
                    param_241 = _e369;
                    let _e370 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_239), (&param_240), (&param_241));
                    broadT = (_e364 - _e370);
                }
                let _e372 = k_4;
                let _e373 = addedR;
                let _e374 = broadR;
                (*c_8).msLobe[_e372] = (_e373 / max(_e374, vec3<f32>(0.0001f, 0.0001f, 0.0001f)));
                let _e379 = k_4;
                let _e380 = addedT;
                let _e381 = broadT;
                (*c_8).msLobeT[_e379] = (_e380 / vec3(max(_e381, 0.0001f)));
                let _e387 = reflected_1;
                let _e388 = addedR;
                let _e390 = transmitted_1;
                let _e392 = addedT;
                param_242 = (((_e387 + _e388) + _e390) + _e392);
                let _e394 = mxc_luminance_u0028_vf3_u003b((&param_242));
                total_1 = max(_e394, 0.000001f);
                let _e396 = addedR;
                let _e397 = addedT;
                param_243 = (_e396 + _e397);
                let _e399 = mxc_luminance_u0028_vf3_u003b((&param_243));
                added = _e399;
                let _e400 = k_4;
                let _e401 = added;
                let _e402 = total_1;
                (*c_8).msPick[_e400] = (0.999f * min((_e401 / _e402), 1f));
                let _e408 = k_4;
                let _e409 = added;
                if (_e409 > 0f) {
                    let _e411 = addedR;
                    param_244 = _e411;
                    let _e412 = mxc_luminance_u0028_vf3_u003b((&param_244));
                    let _e413 = added;
                    local_31 = (_e412 / _e413);
                } else {
                    local_31 = 1f;
                }
                let _e415 = local_31;
                (*c_8).msSplit[_e408] = _e415;
                let _e418 = k_4;
                (*c_8).msT[_e418] = 1f;
            } else {
                let _e421 = k_4;
                let _e422 = ms_3;
                (*c_8).ms[_e421] = _e422;
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e425 = k_4;
            k_4 = (_e425 + 1i);
        }
    }
    return;
}

fn mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_20: ptr<function, MxcLobe>, wo_16: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_245: MxcLobe;
    var param_246: vec3<f32>;
    var param_247: MxcLobe;
    var param_248: vec3<f32>;
    var param_249: vec3<f32>;

    let _e160 = (*l_20);
    param_245 = _e160;
    let _e161 = (*wo_16);
    param_246 = _e161;
    let _e162 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_245), (&param_246));
    let _e163 = (*l_20);
    param_247 = _e163;
    let _e164 = (*wo_16);
    param_248 = _e164;
    param_249 = _e162;
    let _e165 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_247), (&param_248), (&param_249));
    return _e165;
}

fn mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_21: ptr<function, MxcLobe>, wo_17: ptr<function, vec3<f32>>) -> vec3<f32> {
    var white: MxcLobe;
    var param_250: MxcLobe;
    var param_251: vec3<f32>;
    var param_252: MxcLobe;
    var param_253: vec3<f32>;
    var phi_2746_: bool;

    let _e161 = (*l_21).kind;
    let _e162 = (_e161 == 9i);
    phi_2746_ = _e162;
    if !(_e162) {
        let _e165 = (*l_21).kind;
        phi_2746_ = (_e165 == 10i);
    }
    let _e168 = phi_2746_;
    if _e168 {
        let _e169 = (*l_21);
        white = _e169;
        white.c0_ = vec3<f32>(1f, 1f, 1f);
        let _e171 = white;
        param_250 = _e171;
        let _e172 = (*wo_17);
        param_251 = _e172;
        let _e173 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_250), (&param_251));
        return _e173;
    }
    let _e174 = (*l_21);
    param_252 = _e174;
    let _e175 = (*wo_17);
    param_253 = _e175;
    let _e176 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_252), (&param_253));
    return _e176;
}

fn mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b(v_7: ptr<function, vec3<f32>>, fallback: ptr<function, vec3<f32>>) -> vec3<f32> {
    var l2_1: f32;
    var local_32: vec3<f32>;

    let _e157 = (*v_7);
    let _e158 = (*v_7);
    l2_1 = dot(_e157, _e158);
    let _e160 = l2_1;
    if (_e160 > 0.00000000000000000001f) {
        let _e162 = (*v_7);
        let _e163 = l2_1;
        local_32 = (_e162 * inverseSqrt(_e163));
    } else {
        let _e166 = (*fallback);
        local_32 = _e166;
    }
    let _e167 = local_32;
    return _e167;
}

fn mxc_normalmap_u0028_vf3_u003b_vf2_u003b_vf3_u003b_vf3_u003b_vf3_u003b(sampleValue: ptr<function, vec3<f32>>, scale_1: ptr<function, vec2<f32>>, N_1: ptr<function, vec3<f32>>, T_1: ptr<function, vec3<f32>>, B: ptr<function, vec3<f32>>) -> vec3<f32> {
    var v_8: vec3<f32>;
    var param_254: vec3<f32>;
    var param_255: vec3<f32>;

    let _e161 = (*sampleValue);
    v_8 = ((_e161 * 2f) - vec3(1f));
    let _e165 = (*scale_1);
    let _e166 = v_8;
    let _e168 = (_e166.xy * _e165);
    v_8[0u] = _e168.x;
    v_8[1u] = _e168.y;
    let _e173 = (*T_1);
    let _e175 = v_8[0u];
    let _e177 = (*B);
    let _e179 = v_8[1u];
    let _e182 = (*N_1);
    let _e184 = v_8[2u];
    param_254 = (((_e173 * _e175) + (_e177 * _e179)) + (_e182 * _e184));
    let _e187 = (*N_1);
    param_255 = _e187;
    let _e188 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_254), (&param_255));
    return _e188;
}

fn mxc_hsv_to_rgb_u0028_vf3_u003b(hsv: ptr<function, vec3<f32>>) -> vec3<f32> {
    var k_5: vec3<f32>;

    let _e156 = (*hsv)[0u];
    k_5 = clamp((abs(((fract((vec3(_e156) + vec3<f32>(0f, 0.6666667f, 0.33333334f))) * 6f) - vec3(3f))) - vec3(1f)), vec3(0f), vec3(1f));
    let _e170 = (*hsv)[2u];
    let _e171 = k_5;
    let _e173 = (*hsv)[1u];
    return (mix(vec3<f32>(1f, 1f, 1f), _e171, vec3(_e173)) * _e170);
}

fn mxc_address_u0028_f1_u003b_i1_u003b(x_6: ptr<function, f32>, mode: ptr<function, i32>) -> bool {
    let _e155 = (*mode);
    if (_e155 == 0i) {
        let _e157 = (*x_6);
        let _e159 = (*x_6);
        return ((_e157 >= 0f) && (_e159 <= 1f));
    }
    let _e162 = (*mode);
    if (_e162 == 1i) {
        let _e164 = (*x_6);
        (*x_6) = clamp(_e164, 0f, 1f);
    } else {
        let _e166 = (*mode);
        if (_e166 == 2i) {
            let _e168 = (*x_6);
            (*x_6) = fract(_e168);
        } else {
            let _e170 = (*x_6);
            (*x_6) = (1f - abs(((_e170 - (floor((_e170 / 2f)) * 2f)) - 1f)));
        }
    }
    return true;
}

fn mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(image_texture: texture_2d<f32>, image_sampler: sampler, uv_1: ptr<function, vec2<f32>>, fallback_1: ptr<function, vec4<f32>>, uaddress: ptr<function, i32>, vaddress: ptr<function, i32>, filtertype: ptr<function, i32>, missing: ptr<function, bool>) -> vec4<f32> {
    var dx: vec2<f32>;
    var dy: vec2<f32>;
    var st: vec2<f32>;
    var param_256: f32;
    var param_257: i32;
    var param_258: f32;
    var param_259: i32;
    var size_2: vec2<f32>;
    var phi_1680_: bool;

    let _e169 = (*uv_1);
    let _e170 = dpdx(_e169);
    let _e171 = mxc_texture_footprint;
    let _e172 = mxc_texture_footprint;
    dx = (_e170 * vec2<f32>(_e171, -(_e172)));
    let _e176 = (*uv_1);
    let _e177 = dpdy(_e176);
    let _e178 = mxc_texture_footprint;
    let _e179 = mxc_texture_footprint;
    dy = (_e177 * vec2<f32>(_e178, -(_e179)));
    let _e183 = (*uv_1);
    st = _e183;
    let _e184 = (*missing);
    if _e184 {
        let _e185 = (*fallback_1);
        return _e185;
    }
    let _e187 = st[0u];
    param_256 = _e187;
    let _e188 = (*uaddress);
    param_257 = _e188;
    let _e189 = mxc_address_u0028_f1_u003b_i1_u003b((&param_256), (&param_257));
    let _e190 = param_256;
    st[0u] = _e190;
    let _e192 = !(_e189);
    phi_1680_ = _e192;
    if !(_e192) {
        let _e195 = st[1u];
        param_258 = _e195;
        let _e196 = (*vaddress);
        param_259 = _e196;
        let _e197 = mxc_address_u0028_f1_u003b_i1_u003b((&param_258), (&param_259));
        let _e198 = param_258;
        st[1u] = _e198;
        phi_1680_ = !(_e197);
    }
    let _e202 = phi_1680_;
    if _e202 {
        let _e203 = (*fallback_1);
        return _e203;
    }
    let _e205 = st[1u];
    st[1u] = (1f - _e205);
    let _e208 = (*filtertype);
    if (_e208 == 1i) {
        let _e210 = textureDimensions(image_texture, 0i);
        size_2 = vec2<f32>(vec2<i32>(_e210));
        let _e213 = st;
        let _e214 = size_2;
        let _e217 = size_2;
        let _e223 = size_2;
        let _e225 = textureSampleLevel(image_texture, image_sampler, ((min(floor((_e213 * _e214)), (_e217 - vec2(1f))) + vec2(0.5f)) / _e223), 0f);
        return _e225;
    }
    let _e226 = st;
    let _e227 = dx;
    let _e228 = dy;
    let _e229 = textureSampleGrad(image_texture, image_sampler, _e226, _e227, _e228);
    return _e229;
}

fn mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b(g_1: ptr<function, MxcGeometry>, wo_18: ptr<function, vec3<f32>>, c_9: ptr<function, MxcClosure>) {
    var v3_: vec2<f32>;
    var v4_: vec2<f32>;
    var v8_: f32;
    var param_260: vec2<f32>;
    var param_261: vec4<f32>;
    var param_262: i32;
    var param_263: i32;
    var param_264: i32;
    var param_265: bool;
    var v10_: f32;
    var v11_: f32;
    var v13_: f32;
    var param_266: vec2<f32>;
    var param_267: vec4<f32>;
    var param_268: i32;
    var param_269: i32;
    var param_270: i32;
    var param_271: bool;
    var v14_: f32;
    var v20_: f32;
    var param_272: vec2<f32>;
    var param_273: vec4<f32>;
    var param_274: i32;
    var param_275: i32;
    var param_276: i32;
    var param_277: bool;
    var v21_: f32;
    var v25_: f32;
    var param_278: vec2<f32>;
    var param_279: vec4<f32>;
    var param_280: i32;
    var param_281: i32;
    var param_282: i32;
    var param_283: bool;
    var v26_: f32;
    var v28_: f32;
    var param_284: vec2<f32>;
    var param_285: vec4<f32>;
    var param_286: i32;
    var param_287: i32;
    var param_288: i32;
    var param_289: bool;
    var v29_: f32;
    var v31_: f32;
    var v32_: f32;
    var v34_: f32;
    var v35_: f32;
    var v36_: vec3<f32>;
    var v38_: vec3<f32>;
    var v39_: vec3<f32>;
    var param_290: vec3<f32>;
    var v40_: vec3<f32>;
    var v41_: vec3<f32>;
    var v43_: vec3<f32>;
    var v44_: vec3<f32>;
    var v45_: vec3<f32>;
    var v46_: vec3<f32>;
    var v48_: vec3<f32>;
    var param_291: vec2<f32>;
    var param_292: vec4<f32>;
    var param_293: i32;
    var param_294: i32;
    var param_295: i32;
    var param_296: bool;
    var v49_: vec3<f32>;
    var v50_: vec3<f32>;
    var v51_: vec3<f32>;
    var v52_: vec3<f32>;
    var param_297: vec3<f32>;
    var param_298: vec2<f32>;
    var param_299: vec3<f32>;
    var param_300: vec3<f32>;
    var param_301: vec3<f32>;
    var v55_: f32;
    var v56_: f32;
    var v57_: vec2<f32>;
    var lobe0_: MxcLobe;
    var param_302: vec3<f32>;
    var param_303: vec3<f32>;
    var e1_: vec3<f32>;
    var param_304: vec3<f32>;
    var param_305: vec3<f32>;
    var param_306: mat3x3<f32>;
    var param_307: vec3<f32>;
    var param_308: MxcLobe;
    var param_309: vec3<f32>;
    var w2_: vec3<f32>;
    var lobe3_: MxcLobe;
    var param_310: vec3<f32>;
    var param_311: vec3<f32>;
    var param_312: MxcClosure;
    var param_313: vec3<f32>;

    let _e249 = (*g_1).uv;
    v3_ = _e249;
    let _e250 = v3_;
    v4_ = (_e250 * vec2<f32>(3f, 3f));
    let _e253 = mxc_params.missing_textures;
    let _e256 = v4_;
    param_260 = _e256;
    param_261 = vec4<f32>(0f, 0f, 0f, 0f);
    param_262 = 2i;
    param_263 = 2i;
    param_264 = 0i;
    param_265 = ((_e253 & 1u) != 0u);
    let _e257 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_0_texture, mxc_texture_0_sampler, (&param_260), (&param_261), (&param_262), (&param_263), (&param_264), (&param_265));
    v8_ = _e257.x;
    let _e259 = v8_;
    v10_ = max(_e259, 0.00001f);
    let _e261 = v10_;
    v11_ = (0.853f / _e261);
    let _e264 = mxc_params.missing_textures;
    let _e267 = v4_;
    param_266 = _e267;
    param_267 = vec4<f32>(0f, 0f, 0f, 0f);
    param_268 = 2i;
    param_269 = 2i;
    param_270 = 0i;
    param_271 = ((_e264 & 2u) != 0u);
    let _e268 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_1_texture, mxc_texture_1_sampler, (&param_266), (&param_267), (&param_268), (&param_269), (&param_270), (&param_271));
    v13_ = _e268.x;
    let _e270 = v11_;
    let _e271 = v13_;
    v14_ = (_e270 * _e271);
    let _e274 = mxc_params.missing_textures;
    let _e277 = v4_;
    param_272 = _e277;
    param_273 = vec4<f32>(0f, 0f, 0f, 0f);
    param_274 = 2i;
    param_275 = 2i;
    param_276 = 0i;
    param_277 = ((_e274 & 4u) != 0u);
    let _e278 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_2_texture, mxc_texture_2_sampler, (&param_272), (&param_273), (&param_274), (&param_275), (&param_276), (&param_277));
    v20_ = _e278.x;
    let _e280 = v20_;
    v21_ = (0.248f * _e280);
    let _e283 = mxc_params.missing_textures;
    let _e286 = v4_;
    param_278 = _e286;
    param_279 = vec4<f32>(0f, 0f, 0f, 0f);
    param_280 = 2i;
    param_281 = 2i;
    param_282 = 0i;
    param_283 = ((_e283 & 8u) != 0u);
    let _e287 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_3_texture, mxc_texture_3_sampler, (&param_278), (&param_279), (&param_280), (&param_281), (&param_282), (&param_283));
    v25_ = _e287.x;
    let _e289 = v25_;
    v26_ = (0.083f * _e289);
    let _e292 = mxc_params.missing_textures;
    let _e295 = v4_;
    param_284 = _e295;
    param_285 = vec4<f32>(0f, 0f, 0f, 0f);
    param_286 = 2i;
    param_287 = 2i;
    param_288 = 0i;
    param_289 = ((_e292 & 16u) != 0u);
    let _e296 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_4_texture, mxc_texture_4_sampler, (&param_284), (&param_285), (&param_286), (&param_287), (&param_288), (&param_289));
    v28_ = _e296.x;
    let _e298 = v26_;
    let _e299 = v28_;
    v29_ = (_e298 + _e299);
    let _e301 = v29_;
    v31_ = (_e301 - 0.35f);
    let _e303 = v31_;
    v32_ = (_e303 * 0.083f);
    let _e305 = v25_;
    v34_ = (0.787f * _e305);
    let _e307 = v29_;
    let _e308 = v34_;
    v35_ = (_e307 * _e308);
    let _e310 = v32_;
    let _e311 = v35_;
    v36_ = vec3<f32>(_e310, 0f, _e311);
    let _e313 = v36_;
    v38_ = (_e313 + vec3<f32>(0.048065394f, 1f, 0.661876f));
    let _e315 = v38_;
    param_290 = _e315;
    let _e316 = mxc_hsv_to_rgb_u0028_vf3_u003b((&param_290));
    v39_ = _e316;
    let _e317 = v39_;
    let _e318 = v21_;
    v40_ = mix(_e317, vec3<f32>(0.56372f, 0.56372f, 0.56372f), vec3(_e318));
    let _e321 = v40_;
    let _e322 = v28_;
    v41_ = (_e321 * _e322);
    let _e324 = v28_;
    v43_ = (vec3<f32>(0.263273f, 0.263273f, 0.263273f) * _e324);
    let _e326 = v43_;
    let _e327 = v41_;
    let _e328 = v8_;
    v44_ = mix(_e326, _e327, vec3(_e328));
    let _e331 = v44_;
    v45_ = clamp(_e331, vec3<f32>(0f, 0f, 0f), vec3<f32>(1f, 1f, 1f));
    let _e333 = v45_;
    v46_ = clamp(_e333, vec3<f32>(0f, 0f, 0f), vec3<f32>(1f, 1f, 1f));
    let _e336 = mxc_params.missing_textures;
    let _e339 = v4_;
    param_291 = _e339;
    param_292 = vec4<f32>(0f, 0f, 0f, 1f);
    param_293 = 2i;
    param_294 = 2i;
    param_295 = 0i;
    param_296 = ((_e336 & 32u) != 0u);
    let _e340 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_5_texture, mxc_texture_5_sampler, (&param_291), (&param_292), (&param_293), (&param_294), (&param_295), (&param_296));
    v48_ = _e340.xyz;
    let _e343 = (*g_1).N;
    v49_ = _e343;
    let _e345 = (*g_1).T;
    v50_ = _e345;
    let _e347 = (*g_1).B;
    v51_ = _e347;
    let _e348 = v48_;
    param_297 = _e348;
    param_298 = vec2<f32>(1f, 1f);
    let _e349 = v49_;
    param_299 = _e349;
    let _e350 = v50_;
    param_300 = _e350;
    let _e351 = v51_;
    param_301 = _e351;
    let _e352 = mxc_normalmap_u0028_vf3_u003b_vf2_u003b_vf3_u003b_vf3_u003b_vf3_u003b((&param_297), (&param_298), (&param_299), (&param_300), (&param_301));
    v52_ = _e352;
    let _e353 = v14_;
    let _e354 = v14_;
    v55_ = (_e353 * _e354);
    let _e356 = v55_;
    v56_ = clamp(_e356, 0.0000001f, 1f);
    let _e358 = v56_;
    let _e359 = v56_;
    v57_ = vec2<f32>(_e358, _e359);
    (*c_9).emission = vec3<f32>(0f, 0f, 0f);
    (*c_9).transparency = vec3<f32>(0f, 0f, 0f);
    lobe0_.kind = 1i;
    lobe0_.mode = 1i;
    let _e365 = v52_;
    param_302 = _e365;
    let _e367 = (*g_1).N;
    param_303 = _e367;
    let _e368 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_302), (&param_303));
    lobe0_.N = _e368;
    let _e370 = v50_;
    lobe0_.T = _e370;
    let _e372 = v57_;
    lobe0_.alpha = _e372;
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
    let _e385 = lobe0_.N;
    param_304 = _e385;
    let _e387 = lobe0_.T;
    param_305 = _e387;
    let _e388 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_304), (&param_305));
    param_306 = _e388;
    let _e389 = (*wo_18);
    param_307 = _e389;
    let _e390 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_306), (&param_307));
    let _e391 = lobe0_;
    param_308 = _e391;
    param_309 = _e390;
    let _e392 = mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_308), (&param_309));
    e1_ = _e392;
    let _e393 = e1_;
    w2_ = (vec3<f32>(1f, 1f, 1f) - _e393);
    lobe3_.kind = 4i;
    lobe3_.mode = 1i;
    let _e397 = v52_;
    param_310 = _e397;
    let _e399 = (*g_1).N;
    param_311 = _e399;
    let _e400 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_310), (&param_311));
    lobe3_.N = _e400;
    let _e403 = (*g_1).T;
    lobe3_.T = _e403;
    lobe3_.alpha = vec2<f32>(0f, 0f);
    lobe3_.eta = 1.5f;
    lobe3_.etaAbove = 1f;
    let _e408 = v46_;
    lobe3_.c0_ = _e408;
    lobe3_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.p0_ = 0f;
    lobe3_.p1_ = 1f;
    lobe3_.film = vec3<f32>(0f, 0f, 0f);
    lobe3_.tau = vec3<f32>(0f, 0f, 0f);
    lobe3_.tauEta = 1f;
    lobe0_.weight = vec3<f32>(1f, 1f, 1f);
    let _e418 = lobe0_;
    (*c_9).lobes[0i] = _e418;
    let _e421 = w2_;
    lobe3_.weight = _e421;
    let _e423 = lobe3_;
    (*c_9).lobes[1i] = _e423;
    (*c_9).count = 2i;
    let _e427 = (*c_9);
    param_312 = _e427;
    let _e428 = (*wo_18);
    param_313 = _e428;
    mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b((&param_312), (&param_313));
    let _e429 = param_312;
    (*c_9) = _e429;
    return;
}

fn mxc_closure_seed_u0028_u1_u003b(seed_1: ptr<function, u32>) {
    return;
}

fn main_1() {
    var g_2: MxcGeometry;
    var N_2: vec3<f32>;
    var param_314: vec3<f32>;
    var param_315: vec3<f32>;
    var wo_19: vec3<f32>;
    var param_316: vec3<f32>;
    var param_317: vec3<f32>;
    var facing: f32;
    var handedness: f32;
    var frame_4: mat3x3<f32>;
    var param_318: vec3<f32>;
    var param_319: vec3<f32>;
    var param_320: vec3<f32>;
    var param_321: vec3<f32>;
    var objectFrame: mat3x3<f32>;
    var param_322: vec3<f32>;
    var param_323: vec3<f32>;
    var param_324: u32;
    var param_325: u32;
    var param_326: u32;
    var param_327: u32;
    var c_10: MxcClosure;
    var param_328: MxcGeometry;
    var param_329: vec3<f32>;
    var param_330: MxcClosure;
    var radiance: vec3<f32>;
    var lights: i32;
    var kinds: i32;
    var image: bool;
    var n_1: i32;
    var local_33: i32;
    var seed_2: u32;
    var param_331: u32;
    var param_332: u32;
    var param_333: u32;
    var pixel: u32;
    var param_334: u32;
    var param_335: u32;
    var shift: vec4<f32>;
    var param_336: u32;
    var param_337: u32;
    var param_338: u32;
    var param_339: u32;
    var sum: vec3<f32>;
    var b_4: i32;
    var batchLights: i32;
    var batchSamples: i32;
    var local_34: i32;
    var index: u32;
    var choice: vec4<f32>;
    var param_340: u32;
    var param_341: u32;
    var param_342: u32;
    var param_343: u32;
    var param_344: u32;
    var param_345: u32;
    var param_346: u32;
    var param_347: u32;
    var smp: MxcSample;
    var param_348: MxcClosure;
    var param_349: vec3<f32>;
    var param_350: vec3<f32>;
    var above_4: bool;
    var seen: vec3<f32>;
    var local_35: vec3<f32>;
    var local_36: vec3<f32>;
    var param_351: vec3<f32>;
    var param_352: vec3<f32>;
    var param_353: vec3<f32>;
    var w_1: f32;
    var local_37: f32;
    var param_354: vec3<f32>;
    var param_355: f32;
    var param_356: vec3<f32>;
    var param_357: f32;
    var param_358: f32;
    var m_8: vec3<f32>;
    var lightPdf: f32;
    var imageWi: vec3<f32>;
    var imageSeen: vec3<f32>;
    var v_9: vec4<f32>;
    var param_359: u32;
    var param_360: u32;
    var param_361: u32;
    var param_362: vec4<f32>;
    var param_363: f32;
    var param_364: vec3<f32>;
    var param_365: f32;
    var param_366: vec3<f32>;
    var j_2: i32;
    var wi_6: vec3<f32>;
    var incoming: vec3<f32>;
    var use_: bool;
    var strategy: i32;
    var local_38: i32;
    var light: vec4<f32>;
    var directional: bool;
    var param_367: vec3<f32>;
    var param_368: vec3<f32>;
    var d_8: vec3<f32>;
    var d2_: f32;
    var spot: vec4<f32>;
    var f_5: vec3<f32>;
    var pdf_2: f32;
    var param_369: MxcClosure;
    var param_370: vec3<f32>;
    var param_371: vec3<f32>;
    var param_372: bool;
    var param_373: f32;
    var w_2: f32;
    var local_39: f32;
    var param_374: vec3<f32>;
    var param_375: f32;
    var param_376: vec3<f32>;
    var param_377: f32;
    var param_378: f32;
    var w_3: f32;
    var param_379: vec3<f32>;
    var param_380: f32;
    var param_381: f32;
    var coverage: f32;
    var param_382: vec3<f32>;
    var phi_670_: bool;
    var phi_681_: bool;
    var phi_743_: bool;
    var phi_800_: bool;
    var phi_801_: bool;
    var phi_834_: bool;
    var phi_876_: bool;

    mxc_texture_footprint = 1f;
    let _e275 = vPosition_1;
    g_2.P = _e275;
    let _e277 = vObjectPosition_1;
    g_2.Pobj = _e277;
    let _e279 = vNormal_1;
    param_314 = _e279;
    param_315 = vec3<f32>(0f, 0f, 1f);
    let _e280 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_314), (&param_315));
    N_2 = _e280;
    let _e281 = gl_FrontFacing_1;
    if !(_e281) {
        let _e283 = N_2;
        N_2 = -(_e283);
    }
    let _e286 = mxc_view.eye;
    let _e288 = vPosition_1;
    param_316 = (_e286.xyz - _e288);
    let _e290 = N_2;
    param_317 = _e290;
    let _e291 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_316), (&param_317));
    wo_19 = _e291;
    let _e292 = wo_19;
    let _e293 = N_2;
    facing = dot(_e292, _e293);
    let _e295 = facing;
    if (_e295 < 0.01f) {
        let _e297 = N_2;
        let _e298 = facing;
        let _e300 = wo_19;
        N_2 = normalize((_e297 + (_e300 * (0.01f - _e298))));
    }
    let _e305 = vTangent_1[3u];
    handedness = select(1f, -1f, (_e305 < 0f));
    let _e308 = N_2;
    param_318 = _e308;
    let _e309 = vTangent_1;
    param_319 = _e309.xyz;
    let _e311 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_318), (&param_319));
    frame_4 = _e311;
    let _e312 = N_2;
    g_2.N = _e312;
    let _e315 = frame_4[0];
    g_2.T = _e315;
    let _e318 = frame_4[1];
    let _e319 = handedness;
    g_2.B = (_e318 * _e319);
    let _e322 = vObjectNormal_1;
    param_320 = _e322;
    param_321 = vec3<f32>(0f, 0f, 1f);
    let _e323 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_320), (&param_321));
    g_2.Nobj = _e323;
    let _e326 = g_2.Nobj;
    param_322 = _e326;
    let _e327 = vObjectTangent_1;
    param_323 = _e327;
    let _e328 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_322), (&param_323));
    objectFrame = _e328;
    let _e330 = objectFrame[0];
    g_2.Tobj = _e330;
    let _e333 = objectFrame[1];
    let _e334 = handedness;
    g_2.Bobj = (_e333 * _e334);
    let _e337 = vUv_1;
    g_2.uv = _e337;
    g_2.color = vec4<f32>(1f, 1f, 1f, 1f);
    let _e341 = mxc_view.objectToWorld;
    g_2.objectToWorld = _e341;
    let _e344 = mxc_params.frame;
    g_2.frame = _e344;
    let _e347 = mxc_params.time;
    g_2.time = _e347;
    let _e351 = mxc_view.jitter[2u];
    mxc_texture_footprint = _e351;
    let _e352 = mxc_texture_footprint;
    if !((_e352 > 0f)) {
        mxc_texture_footprint = 1f;
    }
    let _e356 = gl_FragCoord_1[0u];
    let _e359 = gl_FragCoord_1[1u];
    let _e363 = mxc_view.counts[2u];
    param_324 = (bitcast<u32>(_e363) + 7u);
    let _e366 = mxc_pcg_u0028_u1_u003b((&param_324));
    param_325 = (u32(_e359) + _e366);
    let _e368 = mxc_pcg_u0028_u1_u003b((&param_325));
    param_326 = (u32(_e356) ^ _e368);
    let _e370 = mxc_pcg_u0028_u1_u003b((&param_326));
    param_327 = _e370;
    mxc_closure_seed_u0028_u1_u003b((&param_327));
    let _e371 = g_2;
    param_328 = _e371;
    let _e372 = wo_19;
    param_329 = _e372;
    mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b((&param_328), (&param_329), (&param_330));
    let _e373 = param_330;
    c_10 = _e373;
    let _e375 = c_10.emission;
    let _e378 = mxc_view.environment[1u];
    radiance = (_e375 * _e378);
    let _e380 = mxc_light_count_u0028_();
    lights = _e380;
    let _e381 = mxc_light_kinds_u0028_();
    kinds = _e381;
    let _e382 = mxc_environment_code_u0028_();
    image = (_e382 == 3i);
    let _e384 = mxc_environment_code_u0028_();
    if (_e384 != 0i) {
        let _e388 = mxc_view.counts[3u];
        local_33 = max(_e388, 1i);
    } else {
        local_33 = 0i;
    }
    let _e390 = local_33;
    n_1 = _e390;
    let _e392 = gl_FragCoord_1[0u];
    let _e395 = gl_FragCoord_1[1u];
    let _e399 = mxc_view.counts[2u];
    param_331 = bitcast<u32>(_e399);
    let _e401 = mxc_pcg_u0028_u1_u003b((&param_331));
    param_332 = (u32(_e395) + _e401);
    let _e403 = mxc_pcg_u0028_u1_u003b((&param_332));
    param_333 = (u32(_e392) + _e403);
    let _e405 = mxc_pcg_u0028_u1_u003b((&param_333));
    seed_2 = _e405;
    let _e407 = gl_FragCoord_1[0u];
    let _e410 = gl_FragCoord_1[1u];
    param_334 = (u32(_e410) + 2654435769u);
    let _e413 = mxc_pcg_u0028_u1_u003b((&param_334));
    param_335 = (u32(_e407) ^ _e413);
    let _e415 = mxc_pcg_u0028_u1_u003b((&param_335));
    pixel = _e415;
    let _e416 = pixel;
    param_336 = _e416;
    let _e417 = mxc_uniform_u0028_u1_u003b((&param_336));
    let _e418 = param_336;
    pixel = _e418;
    let _e419 = pixel;
    param_337 = _e419;
    let _e420 = mxc_uniform_u0028_u1_u003b((&param_337));
    let _e421 = param_337;
    pixel = _e421;
    let _e422 = pixel;
    param_338 = _e422;
    let _e423 = mxc_uniform_u0028_u1_u003b((&param_338));
    let _e424 = param_338;
    pixel = _e424;
    let _e425 = pixel;
    param_339 = _e425;
    let _e426 = mxc_uniform_u0028_u1_u003b((&param_339));
    let _e427 = param_339;
    pixel = _e427;
    shift = vec4<f32>(_e417, _e420, _e423, _e426);
    sum = vec3<f32>(0f, 0f, 0f);
    b_4 = 0i;
    loop {
        let _e429 = b_4;
        let _e430 = n_1;
        let _e431 = lights;
        if (_e429 < max(_e430, select(0i, 1i, (_e431 > 0i)))) {
            let _e436 = b_4;
            let _e438 = lights;
            batchLights = select(0i, _e438, (_e436 == 0i));
            let _e440 = b_4;
            let _e441 = n_1;
            if (_e440 < _e441) {
                let _e443 = image;
                local_34 = (1i + select(0i, 1i, _e443));
            } else {
                local_34 = 0i;
            }
            let _e446 = local_34;
            batchSamples = _e446;
            let _e449 = mxc_view.counts[2u];
            let _e451 = n_1;
            let _e455 = b_4;
            index = ((bitcast<u32>(_e449) * bitcast<u32>(max(_e451, 1i))) + bitcast<u32>(_e455));
            let _e458 = index;
            param_340 = _e458;
            param_341 = 2u;
            let _e459 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_340), (&param_341));
            let _e460 = index;
            param_342 = _e460;
            param_343 = 3u;
            let _e461 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_342), (&param_343));
            let _e462 = index;
            param_344 = _e462;
            param_345 = 5u;
            let _e463 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_344), (&param_345));
            let _e464 = index;
            param_346 = _e464;
            param_347 = 7u;
            let _e465 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_346), (&param_347));
            let _e467 = shift;
            choice = fract((vec4<f32>(_e459, _e461, _e463, _e465) + _e467));
            smp.valid = false;
            smp.evaluate = false;
            smp.delta = false;
            smp.pdf = 0f;
            smp.weight = vec3<f32>(0f, 0f, 0f);
            let _e475 = N_2;
            smp.wi = _e475;
            let _e477 = n_1;
            if (_e477 > 0i) {
                let _e480 = choice[2u];
                let _e482 = choice[3u];
                let _e484 = choice[0u];
                let _e486 = c_10;
                param_348 = _e486;
                let _e487 = wo_19;
                param_349 = _e487;
                param_350 = vec3<f32>(_e480, _e482, _e484);
                let _e488 = mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b((&param_348), (&param_349), (&param_350));
                smp = _e488;
            }
            let _e490 = smp.wi;
            let _e491 = N_2;
            above_4 = (dot(_e490, _e491) > 0f);
            let _e495 = smp.valid;
            if _e495 {
                let _e496 = above_4;
                if _e496 {
                    let _e498 = smp.wi;
                    local_36 = _e498;
                } else {
                    let _e499 = wo_19;
                    param_351 = -(_e499);
                    let _e502 = smp.wi;
                    param_352 = _e502;
                    let _e503 = mxc_exit_direction_u0028_vf3_u003b_vf3_u003b((&param_351), (&param_352));
                    local_36 = _e503;
                }
                let _e504 = local_36;
                param_353 = _e504;
                let _e505 = mxc_environment_u0028_vf3_u003b((&param_353));
                local_35 = _e505;
            } else {
                local_35 = vec3<f32>(0f, 0f, 0f);
            }
            let _e506 = local_35;
            seen = _e506;
            let _e507 = b_4;
            let _e508 = n_1;
            let _e511 = smp.valid;
            let _e512 = ((_e507 < _e508) && _e511);
            phi_670_ = _e512;
            if _e512 {
                let _e514 = smp.evaluate;
                phi_670_ = !(_e514);
            }
            let _e517 = phi_670_;
            if _e517 {
                let _e518 = image;
                let _e519 = above_4;
                let _e520 = (_e518 && _e519);
                phi_681_ = _e520;
                if _e520 {
                    let _e522 = smp.delta;
                    phi_681_ = !(_e522);
                }
                let _e525 = phi_681_;
                if _e525 {
                    let _e527 = smp.wi;
                    param_354 = _e527;
                    let _e530 = mxc_view.environment[2u];
                    param_355 = _e530;
                    let _e531 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_354), (&param_355));
                    param_356 = _e531;
                    let _e532 = mxc_env_pdf_u0028_vf3_u003b((&param_356));
                    let _e534 = smp.pdf;
                    param_357 = _e534;
                    param_358 = _e532;
                    let _e535 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_357), (&param_358));
                    local_37 = _e535;
                } else {
                    local_37 = 1f;
                }
                let _e536 = local_37;
                w_1 = _e536;
                let _e537 = w_1;
                let _e539 = smp.weight;
                let _e541 = seen;
                let _e543 = sum;
                sum = (_e543 + ((_e539 * _e537) * _e541));
            }
            m_8 = vec3<f32>(0f, 0f, 0f);
            lightPdf = 0f;
            let _e545 = N_2;
            imageWi = _e545;
            imageSeen = vec3<f32>(0f, 0f, 0f);
            let _e546 = image;
            let _e547 = b_4;
            let _e548 = n_1;
            if (_e546 && (_e547 < _e548)) {
                let _e552 = choice[1u];
                let _e553 = seed_2;
                param_359 = _e553;
                let _e554 = mxc_uniform_u0028_u1_u003b((&param_359));
                let _e555 = param_359;
                seed_2 = _e555;
                let _e556 = seed_2;
                param_360 = _e556;
                let _e557 = mxc_uniform_u0028_u1_u003b((&param_360));
                let _e558 = param_360;
                seed_2 = _e558;
                let _e559 = seed_2;
                param_361 = _e559;
                let _e560 = mxc_uniform_u0028_u1_u003b((&param_361));
                let _e561 = param_361;
                seed_2 = _e561;
                v_9 = vec4<f32>(_e552, _e554, _e557, _e560);
                let _e563 = v_9;
                param_362 = _e563;
                let _e564 = mxc_env_sample_u0028_vf4_u003b_f1_u003b((&param_362), (&param_363));
                let _e565 = param_363;
                lightPdf = _e565;
                m_8 = _e564;
                let _e566 = m_8;
                param_364 = _e566;
                let _e569 = mxc_view.environment[2u];
                param_365 = _e569;
                let _e570 = mxc_env_to_world_u0028_vf3_u003b_f1_u003b((&param_364), (&param_365));
                imageWi = _e570;
                let _e571 = lightPdf;
                let _e572 = (_e571 > 0f);
                phi_743_ = _e572;
                if _e572 {
                    let _e573 = imageWi;
                    let _e574 = N_2;
                    phi_743_ = (dot(_e573, _e574) > 0f);
                }
                let _e578 = phi_743_;
                if _e578 {
                    let _e579 = imageWi;
                    param_366 = _e579;
                    let _e580 = mxc_environment_u0028_vf3_u003b((&param_366));
                    imageSeen = _e580;
                }
            }
            j_2 = 0i;
            loop {
                let _e581 = j_2;
                let _e582 = batchLights;
                let _e583 = batchSamples;
                if (_e581 < (_e582 + _e583)) {
                    let _e586 = N_2;
                    wi_6 = _e586;
                    incoming = vec3<f32>(0f, 0f, 0f);
                    use_ = true;
                    let _e587 = n_1;
                    let _e589 = j_2;
                    let _e590 = batchLights;
                    if ((_e587 == 0i) || (_e589 < _e590)) {
                        local_38 = 0i;
                    } else {
                        let _e593 = j_2;
                        let _e594 = batchLights;
                        local_38 = select(2i, 1i, (_e593 == ((_e594 + 1i) - 1i)));
                    }
                    let _e599 = local_38;
                    strategy = _e599;
                    let _e600 = strategy;
                    if (_e600 == 0i) {
                        let _e602 = j_2;
                        let _e605 = mxc_view.lightVector[_e602];
                        light = _e605;
                        let _e606 = j_2;
                        let _e609 = mxc_view.lightRadiance[_e606];
                        incoming = _e609.xyz;
                        let _e611 = kinds;
                        let _e612 = (_e611 == 1i);
                        phi_801_ = _e612;
                        if !(_e612) {
                            let _e614 = kinds;
                            let _e616 = ((_e614 & 1i) != 0i);
                            phi_800_ = _e616;
                            if _e616 {
                                let _e618 = light[3u];
                                phi_800_ = (_e618 == 0f);
                            }
                            let _e621 = phi_800_;
                            phi_801_ = _e621;
                        }
                        let _e623 = phi_801_;
                        directional = _e623;
                        let _e624 = directional;
                        if _e624 {
                            let _e625 = light;
                            param_367 = _e625.xyz;
                            let _e627 = N_2;
                            param_368 = _e627;
                            let _e628 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_367), (&param_368));
                            wi_6 = _e628;
                        } else {
                            let _e629 = light;
                            let _e631 = vPosition_1;
                            d_8 = (_e629.xyz - _e631);
                            let _e633 = d_8;
                            let _e634 = d_8;
                            d2_ = max(dot(_e633, _e634), 0.00000001f);
                            let _e637 = d_8;
                            let _e638 = d2_;
                            wi_6 = (_e637 * inverseSqrt(_e638));
                            let _e641 = d2_;
                            let _e642 = incoming;
                            incoming = (_e642 / vec3(_e641));
                            let _e645 = kinds;
                            let _e647 = ((_e645 & 4i) != 0i);
                            phi_834_ = _e647;
                            if _e647 {
                                let _e649 = light[3u];
                                phi_834_ = (_e649 == 2f);
                            }
                            let _e652 = phi_834_;
                            if _e652 {
                                let _e653 = j_2;
                                let _e656 = mxc_view.lightSpot[_e653];
                                spot = _e656;
                                let _e658 = spot[3u];
                                let _e659 = j_2;
                                let _e663 = mxc_view.lightRadiance[_e659][3u];
                                let _e664 = wi_6;
                                let _e666 = spot;
                                let _e670 = incoming;
                                incoming = (_e670 * smoothstep(_e658, _e663, dot(-(_e664), _e666.xyz)));
                            }
                        }
                    } else {
                        let _e672 = strategy;
                        if (_e672 == 1i) {
                            let _e675 = smp.wi;
                            wi_6 = _e675;
                            let _e676 = seen;
                            incoming = _e676;
                            let _e678 = smp.valid;
                            let _e680 = smp.evaluate;
                            use_ = (_e678 && _e680);
                        } else {
                            let _e682 = imageWi;
                            wi_6 = _e682;
                            let _e683 = imageSeen;
                            incoming = _e683;
                            let _e684 = lightPdf;
                            let _e685 = (_e684 > 0f);
                            phi_876_ = _e685;
                            if _e685 {
                                let _e686 = imageWi;
                                let _e687 = N_2;
                                phi_876_ = (dot(_e686, _e687) > 0f);
                            }
                            let _e691 = phi_876_;
                            use_ = _e691;
                        }
                    }
                    let _e692 = strategy;
                    let _e694 = c_10;
                    param_369 = _e694;
                    let _e695 = wo_19;
                    param_370 = _e695;
                    let _e696 = wi_6;
                    param_371 = _e696;
                    param_372 = (_e692 != 0i);
                    let _e697 = mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b((&param_369), (&param_370), (&param_371), (&param_372), (&param_373));
                    let _e698 = param_373;
                    pdf_2 = _e698;
                    f_5 = _e697;
                    let _e699 = strategy;
                    if (_e699 == 0i) {
                        let _e701 = f_5;
                        let _e702 = incoming;
                        let _e704 = radiance;
                        radiance = (_e704 + (_e701 * _e702));
                    } else {
                        let _e706 = strategy;
                        if (_e706 == 1i) {
                            let _e708 = use_;
                            let _e709 = pdf_2;
                            if (_e708 && (_e709 > 0f)) {
                                let _e712 = image;
                                let _e713 = above_4;
                                if (_e712 && _e713) {
                                    let _e715 = wi_6;
                                    param_374 = _e715;
                                    let _e718 = mxc_view.environment[2u];
                                    param_375 = _e718;
                                    let _e719 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_374), (&param_375));
                                    param_376 = _e719;
                                    let _e720 = mxc_env_pdf_u0028_vf3_u003b((&param_376));
                                    let _e721 = pdf_2;
                                    param_377 = _e721;
                                    param_378 = _e720;
                                    let _e722 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_377), (&param_378));
                                    local_39 = _e722;
                                } else {
                                    local_39 = 1f;
                                }
                                let _e723 = local_39;
                                w_2 = _e723;
                                let _e724 = w_2;
                                let _e725 = f_5;
                                let _e727 = pdf_2;
                                let _e730 = incoming;
                                let _e732 = sum;
                                sum = (_e732 + (((_e725 * _e724) / vec3(_e727)) * _e730));
                            }
                        } else {
                            let _e734 = use_;
                            if _e734 {
                                let _e735 = m_8;
                                param_379 = _e735;
                                let _e736 = mxc_env_pdf_u0028_vf3_u003b((&param_379));
                                param_380 = _e736;
                                let _e737 = pdf_2;
                                param_381 = _e737;
                                let _e738 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_380), (&param_381));
                                w_3 = _e738;
                                let _e739 = w_3;
                                let _e740 = f_5;
                                let _e742 = incoming;
                                let _e744 = lightPdf;
                                let _e747 = sum;
                                sum = (_e747 + (((_e740 * _e739) * _e742) / vec3(_e744)));
                            }
                        }
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e749 = j_2;
                    j_2 = (_e749 + 1i);
                }
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e751 = b_4;
            b_4 = (_e751 + 1i);
        }
    }
    let _e753 = sum;
    let _e754 = n_1;
    let _e759 = radiance;
    radiance = (_e759 + (_e753 / vec3(f32(max(_e754, 1i)))));
    let _e762 = c_10.transparency;
    param_382 = _e762;
    let _e763 = mxc_luminance_u0028_vf3_u003b((&param_382));
    coverage = (1f - clamp(_e763, 0f, 1f));
    let _e766 = radiance;
    let _e767 = coverage;
    outColor = vec4<f32>(_e766.x, _e766.y, _e766.z, _e767);
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
