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
    let _e153 = (*c);
    return dot(_e153, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b(l: ptr<function, MxcLobe>, mu: ptr<function, f32>) -> vec3<f32> {
    return vec3<f32>(1f, 1f, 1f);
}

fn mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_1: ptr<function, MxcLobe>) -> bool {
    return false;
}

fn mxc_mean_u0028_vf3_u003b(c_1: ptr<function, vec3<f32>>) -> f32 {
    let _e154 = (*c_1)[0u];
    let _e156 = (*c_1)[1u];
    let _e159 = (*c_1)[2u];
    return (((_e154 + _e156) + _e159) * 0.33333334f);
}

fn mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b(cosi: ptr<function, f32>, eta: ptr<function, f32>) -> f32 {
    var sin2t: f32;
    var cost: f32;
    var rs: f32;
    var rp: f32;

    let _e158 = (*eta);
    if (abs((_e158 - 1f)) < 0.000001f) {
        return 0f;
    }
    let _e162 = (*cosi);
    let _e163 = (*cosi);
    let _e166 = (*eta);
    let _e167 = (*eta);
    sin2t = ((1f - (_e162 * _e163)) / (_e166 * _e167));
    let _e170 = sin2t;
    if (_e170 >= 1f) {
        return 1f;
    }
    let _e172 = sin2t;
    cost = sqrt((1f - _e172));
    let _e175 = (*cosi);
    let _e176 = (*eta);
    let _e177 = cost;
    let _e180 = (*cosi);
    let _e181 = (*eta);
    let _e182 = cost;
    rs = ((_e175 - (_e176 * _e177)) / (_e180 + (_e181 * _e182)));
    let _e186 = (*eta);
    let _e187 = (*cosi);
    let _e189 = cost;
    let _e191 = (*eta);
    let _e192 = (*cosi);
    let _e194 = cost;
    rp = (((_e186 * _e187) - _e189) / ((_e191 * _e192) + _e194));
    let _e197 = rs;
    let _e198 = rs;
    let _e200 = rp;
    let _e201 = rp;
    return (0.5f * ((_e197 * _e198) + (_e200 * _e201)));
}

fn mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_2: ptr<function, MxcLobe>, above: ptr<function, bool>) -> f32 {
    var local: f32;

    let _e155 = (*above);
    if _e155 {
        let _e157 = (*l_2).eta;
        local = _e157;
    } else {
        let _e159 = (*l_2).eta;
        local = (1f / _e159);
    }
    let _e161 = local;
    return _e161;
}

fn mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b(l_3: ptr<function, MxcLobe>, cosh_: ptr<function, f32>, above_1: ptr<function, bool>) -> vec3<f32> {
    var f: vec3<f32>;
    var param: MxcLobe;
    var param_1: bool;
    var param_2: f32;
    var param_3: f32;

    f = vec3<f32>(1f, 1f, 1f);
    let _e161 = (*l_3).kind;
    if (_e161 == 1i) {
        let _e163 = (*l_3);
        param = _e163;
        let _e164 = (*above_1);
        param_1 = _e164;
        let _e165 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param), (&param_1));
        let _e166 = (*cosh_);
        param_2 = _e166;
        param_3 = _e165;
        let _e167 = mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b((&param_2), (&param_3));
        f = vec3(_e167);
    }
    let _e169 = f;
    return _e169;
}

fn mxc_rough_alpha_u0028_vf2_u003b(alpha: ptr<function, vec2<f32>>) -> vec2<f32> {
    let _e153 = (*alpha);
    return max(_e153, vec2<f32>(0.0001f, 0.0001f));
}

fn mxc_ggx_d_u0028_vf3_u003b_vf2_u003b(m: ptr<function, vec3<f32>>, alpha_1: ptr<function, vec2<f32>>) -> f32 {
    var param_4: vec2<f32>;
    var s: vec3<f32>;
    var d: f32;

    let _e158 = (*m)[2u];
    if (_e158 <= 0f) {
        return 0f;
    }
    let _e160 = (*alpha_1);
    param_4 = _e160;
    let _e161 = mxc_rough_alpha_u0028_vf2_u003b((&param_4));
    (*alpha_1) = _e161;
    let _e163 = (*m)[0u];
    let _e165 = (*alpha_1)[0u];
    let _e168 = (*m)[1u];
    let _e170 = (*alpha_1)[1u];
    let _e173 = (*m)[2u];
    s = vec3<f32>((_e163 / _e165), (_e168 / _e170), _e173);
    let _e175 = s;
    let _e176 = s;
    d = dot(_e175, _e176);
    let _e179 = (*alpha_1)[0u];
    let _e182 = (*alpha_1)[1u];
    let _e184 = d;
    let _e186 = d;
    return (1f / ((((3.1415927f * _e179) * _e182) * _e184) * _e186));
}

fn mxc_sqr_u0028_f1_u003b(x: ptr<function, f32>) -> f32 {
    let _e153 = (*x);
    let _e154 = (*x);
    return (_e153 * _e154);
}

fn mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b(v: ptr<function, vec3<f32>>, alpha_2: ptr<function, vec2<f32>>) -> f32 {
    var param_5: vec2<f32>;
    var z2_: f32;
    var a2_: f32;
    var param_6: f32;
    var param_7: f32;

    let _e159 = (*alpha_2);
    param_5 = _e159;
    let _e160 = mxc_rough_alpha_u0028_vf2_u003b((&param_5));
    (*alpha_2) = _e160;
    let _e162 = (*v)[2u];
    let _e164 = (*v)[2u];
    z2_ = (_e162 * _e164);
    let _e166 = z2_;
    if (_e166 <= 0f) {
        return 10000000000f;
    }
    let _e169 = (*alpha_2)[0u];
    let _e171 = (*v)[0u];
    param_6 = (_e169 * _e171);
    let _e173 = mxc_sqr_u0028_f1_u003b((&param_6));
    let _e175 = (*alpha_2)[1u];
    let _e177 = (*v)[1u];
    param_7 = (_e175 * _e177);
    let _e179 = mxc_sqr_u0028_f1_u003b((&param_7));
    let _e181 = z2_;
    a2_ = ((_e173 + _e179) / _e181);
    let _e183 = a2_;
    return (0.5f * (-1f + sqrt((1f + _e183))));
}

fn mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b(v_1: ptr<function, vec3<f32>>, alpha_3: ptr<function, vec2<f32>>) -> f32 {
    var param_8: vec3<f32>;
    var param_9: vec2<f32>;

    let _e156 = (*v_1);
    param_8 = _e156;
    let _e157 = (*alpha_3);
    param_9 = _e157;
    let _e158 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_8), (&param_9));
    return (1f / (1f + _e158));
}

fn mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo: ptr<function, vec3<f32>>, m_1: ptr<function, vec3<f32>>, alpha_4: ptr<function, vec2<f32>>) -> f32 {
    var param_10: vec3<f32>;
    var param_11: vec2<f32>;
    var param_12: vec3<f32>;
    var param_13: vec2<f32>;

    let _e160 = (*wo)[2u];
    if (_e160 <= 0f) {
        return 0f;
    }
    let _e162 = (*wo);
    param_10 = _e162;
    let _e163 = (*alpha_4);
    param_11 = _e163;
    let _e164 = mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b((&param_10), (&param_11));
    let _e165 = (*wo);
    let _e166 = (*m_1);
    let _e170 = (*m_1);
    param_12 = _e170;
    let _e171 = (*alpha_4);
    param_13 = _e171;
    let _e172 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_12), (&param_13));
    let _e175 = (*wo)[2u];
    return (((_e164 * max(dot(_e165, _e166), 0f)) * _e172) / _e175);
}

fn mxc_is_delta_u0028_vf2_u003b(alpha_5: ptr<function, vec2<f32>>) -> bool {
    let _e154 = (*alpha_5)[0u];
    let _e156 = (*alpha_5)[1u];
    return (max(_e154, _e156) < 0.0001f);
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
    var phi_2851_: bool;
    var phi_2932_: bool;

    let _e174 = (*l_4).kind;
    switch _e174 {
        case 2, 3, 1: {
            let _e188 = (*l_4).alpha;
            param_14 = _e188;
            let _e189 = mxc_is_delta_u0028_vf2_u003b((&param_14));
            if _e189 {
                return 0f;
            }
            let _e191 = (*wo_1)[2u];
            above_2 = (_e191 > 0f);
            let _e193 = above_2;
            if _e193 {
                let _e194 = (*wo_1);
                local_1 = _e194;
            } else {
                let _e195 = (*wo_1);
                local_1 = -(_e195);
            }
            let _e197 = local_1;
            o = _e197;
            let _e198 = above_2;
            if _e198 {
                let _e199 = (*wi);
                local_2 = _e199;
            } else {
                let _e200 = (*wi);
                local_2 = -(_e200);
            }
            let _e202 = local_2;
            i = _e202;
            let _e204 = i[2u];
            if (_e204 > 0f) {
                let _e206 = o;
                let _e207 = i;
                h = normalize((_e206 + _e207));
                let _e210 = o;
                param_15 = _e210;
                let _e211 = h;
                param_16 = _e211;
                let _e213 = (*l_4).alpha;
                param_17 = _e213;
                let _e214 = mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_15), (&param_16), (&param_17));
                let _e215 = o;
                let _e216 = h;
                p = (_e214 / (4f * max(dot(_e215, _e216), 0.000001f)));
                let _e222 = (*l_4).kind;
                if (_e222 == 2i) {
                    let _e224 = p;
                    return _e224;
                }
                let _e226 = (*l_4).mode;
                if ((_e226 & 1i) == 0i) {
                    return 0f;
                }
                let _e229 = o;
                let _e230 = h;
                let _e233 = (*l_4);
                param_18 = _e233;
                param_19 = max(dot(_e229, _e230), 0f);
                let _e234 = above_2;
                param_20 = _e234;
                let _e235 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_18), (&param_19), (&param_20));
                param_21 = _e235;
                let _e236 = mxc_mean_u0028_vf3_u003b((&param_21));
                fr = _e236;
                let _e237 = p;
                let _e238 = (*l_4);
                param_22 = _e238;
                let _e239 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_22));
                phi_2932_ = _e239;
                if _e239 {
                    let _e241 = (*l_4).mode;
                    phi_2932_ = ((_e241 & 1i) != 0i);
                }
                let _e245 = phi_2932_;
                let _e246 = fr;
                return (_e237 * select(1f, _e246, _e245));
            }
            return 0f;
        }
        default: {
            let _e176 = (*wo_1)[2u];
            let _e177 = (_e176 > 0f);
            phi_2851_ = _e177;
            if _e177 {
                let _e179 = (*wi)[2u];
                phi_2851_ = (_e179 > 0f);
            }
            let _e182 = phi_2851_;
            if _e182 {
                let _e184 = (*wi)[2u];
                local_3 = (_e184 * 0.31830987f);
            } else {
                local_3 = 0f;
            }
            let _e186 = local_3;
            return _e186;
        }
    }
}

fn mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b(sigma: ptr<function, f32>, wo_2: ptr<function, vec3<f32>>, wi_1: ptr<function, vec3<f32>>) -> f32 {
    var a: f32;
    var s_1: f32;
    var t: f32;
    var local_4: f32;

    let _e159 = (*sigma);
    a = (1f / (1f + (0.2877934f * _e159)));
    let _e163 = (*wi_1);
    let _e164 = (*wo_2);
    let _e167 = (*wi_1)[2u];
    let _e169 = (*wo_2)[2u];
    s_1 = (dot(_e163, _e164) - (_e167 * _e169));
    let _e172 = s_1;
    if (_e172 > 0f) {
        let _e175 = (*wi_1)[2u];
        let _e177 = (*wo_2)[2u];
        local_4 = max(max(_e175, _e177), 0.000001f);
    } else {
        local_4 = 1f;
    }
    let _e180 = local_4;
    t = _e180;
    let _e181 = a;
    let _e182 = (*sigma);
    let _e183 = a;
    let _e185 = s_1;
    let _e187 = t;
    return ((_e181 + (((_e182 * _e183) * _e185) / _e187)) * 0.31830987f);
}

fn mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo_3: ptr<function, vec3<f32>>, wi_2: ptr<function, vec3<f32>>, alpha_6: ptr<function, vec2<f32>>) -> f32 {
    var param_23: vec3<f32>;
    var param_24: vec2<f32>;
    var param_25: vec3<f32>;
    var param_26: vec2<f32>;

    let _e159 = (*wo_3);
    param_23 = _e159;
    let _e160 = (*alpha_6);
    param_24 = _e160;
    let _e161 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_23), (&param_24));
    let _e163 = (*wi_2);
    param_25 = _e163;
    let _e164 = (*alpha_6);
    param_26 = _e164;
    let _e165 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_25), (&param_26));
    return (1f / ((1f + _e161) + _e165));
}

fn mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_5: ptr<function, MxcLobe>, wo_4: ptr<function, vec3<f32>>, wi_3: ptr<function, vec3<f32>>) -> vec3<f32> {
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
    var phi_2021_: bool;
    var phi_2028_: bool;

    let _e167 = (*wo_4)[2u];
    let _e168 = (_e167 <= 0f);
    phi_2021_ = _e168;
    if !(_e168) {
        let _e171 = (*wi_3)[2u];
        phi_2021_ = (_e171 <= 0f);
    }
    let _e174 = phi_2021_;
    phi_2028_ = _e174;
    if !(_e174) {
        let _e177 = (*l_5).alpha;
        param_27 = _e177;
        let _e178 = mxc_is_delta_u0028_vf2_u003b((&param_27));
        phi_2028_ = _e178;
    }
    let _e180 = phi_2028_;
    if _e180 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e181 = (*wo_4);
    let _e182 = (*wi_3);
    h_1 = normalize((_e181 + _e182));
    let _e185 = (*wo_4);
    let _e186 = h_1;
    let _e189 = (*l_5);
    param_28 = _e189;
    param_29 = max(dot(_e185, _e186), 0f);
    param_30 = true;
    let _e190 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_28), (&param_29), (&param_30));
    f_1 = _e190;
    let _e192 = (*l_5).kind;
    if (_e192 == 1i) {
        let _e195 = (*l_5).c0_;
        let _e196 = f_1;
        f_1 = (_e196 * _e195);
    }
    let _e198 = f_1;
    let _e199 = h_1;
    param_31 = _e199;
    let _e201 = (*l_5).alpha;
    param_32 = _e201;
    let _e202 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_31), (&param_32));
    let _e204 = (*wo_4);
    param_33 = _e204;
    let _e205 = (*wi_3);
    param_34 = _e205;
    let _e207 = (*l_5).alpha;
    param_35 = _e207;
    let _e208 = mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_33), (&param_34), (&param_35));
    let _e211 = (*wo_4)[2u];
    return (((_e198 * _e202) * _e208) / vec3((4f * _e211)));
}

fn mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_6: ptr<function, MxcLobe>, wo_5: ptr<function, vec3<f32>>, wi_4: ptr<function, vec3<f32>>) -> vec3<f32> {
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
    var phi_2784_: bool;
    var phi_2799_: bool;

    let _e170 = (*l_6).kind;
    switch _e170 {
        case 1: {
            let _e172 = (*wo_5)[2u];
            let _e174 = (*wi_4)[2u];
            if ((_e172 * _e174) > 0f) {
                let _e178 = (*l_6).mode;
                if ((_e178 & 1i) == 0i) {
                    return vec3<f32>(0f, 0f, 0f);
                }
                let _e182 = (*wo_5)[2u];
                if (_e182 < 0f) {
                    let _e184 = (*l_6);
                    m_2 = _e184;
                    let _e186 = (*l_6).eta;
                    m_2.eta = (1f / _e186);
                    m_2.c0_ = vec3<f32>(1f, 1f, 1f);
                    let _e190 = (*wo_5);
                    let _e192 = (*wi_4);
                    let _e194 = m_2;
                    param_36 = _e194;
                    param_37 = -(_e190);
                    param_38 = -(_e192);
                    let _e195 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_36), (&param_37), (&param_38));
                    return _e195;
                }
                let _e196 = (*l_6);
                param_39 = _e196;
                let _e197 = (*wo_5);
                param_40 = _e197;
                let _e198 = (*wi_4);
                param_41 = _e198;
                let _e199 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_39), (&param_40), (&param_41));
                return _e199;
            }
            return vec3<f32>(0f, 0f, 0f);
        }
        case 3, 2: {
            let _e201 = (*l_6).kind;
            let _e202 = (_e201 == 3i);
            phi_2784_ = _e202;
            if _e202 {
                let _e204 = (*l_6).mode;
                phi_2784_ = ((_e204 & 1i) == 0i);
            }
            let _e208 = phi_2784_;
            if _e208 {
                return vec3<f32>(0f, 0f, 0f);
            }
            let _e209 = (*l_6);
            param_42 = _e209;
            let _e210 = (*wo_5);
            param_43 = _e210;
            let _e211 = (*wi_4);
            param_44 = _e211;
            let _e212 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_42), (&param_43), (&param_44));
            return _e212;
        }
        case 4: {
            let _e214 = (*wo_5)[2u];
            let _e215 = (_e214 > 0f);
            phi_2799_ = _e215;
            if _e215 {
                let _e217 = (*wi_4)[2u];
                phi_2799_ = (_e217 > 0f);
            }
            let _e220 = phi_2799_;
            if _e220 {
                let _e222 = (*l_6).c0_;
                let _e224 = (*l_6).p0_;
                param_45 = _e224;
                let _e225 = (*wo_5);
                param_46 = _e225;
                let _e226 = (*wi_4);
                param_47 = _e226;
                let _e227 = mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b((&param_45), (&param_46), (&param_47));
                let _e230 = (*wi_4)[2u];
                local_5 = ((_e222 * _e227) * _e230);
            } else {
                local_5 = vec3<f32>(0f, 0f, 0f);
            }
            let _e232 = local_5;
            return _e232;
        }
        default: {
            return vec3<f32>(0f, 0f, 0f);
        }
    }
}

fn mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_7: ptr<function, MxcLobe>, transmitted: ptr<function, bool>) -> MxcLobe {
    var m_3: MxcLobe;
    var local_6: i32;

    let _e156 = (*l_7);
    m_3 = _e156;
    let _e158 = (*l_7).alpha;
    let _e159 = (*transmitted);
    m_3.alpha = min((_e158 * select(1.5f, 3f, _e159)), vec2<f32>(1f, 1f));
    let _e164 = (*transmitted);
    if _e164 {
        let _e166 = (*l_7).mode;
        local_6 = (_e166 & -2i);
    } else {
        let _e169 = (*l_7).mode;
        local_6 = (_e169 & -3i);
    }
    let _e171 = local_6;
    m_3.mode = _e171;
    let _e174 = (*l_7).kind;
    if (_e174 == 1i) {
        m_3.c0_ = vec3<f32>(1f, 1f, 1f);
        m_3.c1_ = vec3<f32>(1f, 1f, 1f);
    }
    let _e178 = m_3;
    return _e178;
}

fn mxc_to_local_u0028_mf33_u003b_vf3_u003b(frame: ptr<function, mat3x3<f32>>, v_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e154 = (*v_2);
    let _e156 = (*frame)[0];
    let _e158 = (*v_2);
    let _e160 = (*frame)[1];
    let _e162 = (*v_2);
    let _e164 = (*frame)[2];
    return vec3<f32>(dot(_e154, _e156), dot(_e158, _e160), dot(_e162, _e164));
}

fn mxc_frame_u0028_vf3_u003b_vf3_u003b(N: ptr<function, vec3<f32>>, T: ptr<function, vec3<f32>>) -> mat3x3<f32> {
    var t_1: vec3<f32>;
    var l2_: f32;
    var s_2: f32;
    var a_1: f32;
    var b: f32;

    let _e159 = (*T);
    let _e160 = (*N);
    let _e161 = (*N);
    let _e162 = (*T);
    t_1 = (_e159 - (_e160 * dot(_e161, _e162)));
    let _e166 = t_1;
    let _e167 = t_1;
    l2_ = dot(_e166, _e167);
    let _e169 = l2_;
    if !((_e169 > 0.000000000001f)) {
        let _e173 = (*N)[2u];
        s_2 = select(-1f, 1f, (_e173 >= 0f));
        let _e176 = s_2;
        let _e178 = (*N)[2u];
        a_1 = (-1f / (_e176 + _e178));
        let _e182 = (*N)[0u];
        let _e184 = (*N)[1u];
        let _e186 = a_1;
        b = ((_e182 * _e184) * _e186);
        let _e188 = s_2;
        let _e190 = (*N)[0u];
        let _e193 = (*N)[0u];
        let _e195 = a_1;
        let _e198 = s_2;
        let _e199 = b;
        let _e201 = s_2;
        let _e204 = (*N)[0u];
        t_1 = vec3<f32>((1f + (((_e188 * _e190) * _e193) * _e195)), (_e198 * _e199), (-(_e201) * _e204));
    } else {
        let _e207 = l2_;
        let _e209 = t_1;
        t_1 = (_e209 * inverseSqrt(_e207));
    }
    let _e211 = t_1;
    let _e212 = (*N);
    let _e213 = t_1;
    let _e214 = cross(_e212, _e213);
    let _e215 = (*N);
    return mat3x3<f32>(vec3<f32>(_e211.x, _e211.y, _e211.z), vec3<f32>(_e214.x, _e214.y, _e214.z), vec3<f32>(_e215.x, _e215.y, _e215.z));
}

fn mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b(c_2: ptr<function, MxcClosure>, wo_6: ptr<function, vec3<f32>>, wi_5: ptr<function, vec3<f32>>, wantPdf: ptr<function, bool>, pdf: ptr<function, f32>) -> vec3<f32> {
    var f_2: vec3<f32>;
    var p_1: f32;
    var k: i32;
    var l_8: MxcLobe;
    var frame_1: mat3x3<f32>;
    var param_48: vec3<f32>;
    var param_49: vec3<f32>;
    var o_1: vec3<f32>;
    var param_50: mat3x3<f32>;
    var param_51: vec3<f32>;
    var i_1: vec3<f32>;
    var param_52: mat3x3<f32>;
    var param_53: vec3<f32>;
    var fk: vec3<f32>;
    var pk: f32;
    var passes: i32;
    var pass_: i32;
    var shaped: bool;
    var m_4: MxcLobe;
    var local_7: MxcLobe;
    var param_54: MxcLobe;
    var param_55: bool;
    var scale: vec3<f32>;
    var local_8: vec3<f32>;
    var local_9: vec3<f32>;
    var local_10: vec3<f32>;
    var param_56: MxcLobe;
    var param_57: vec3<f32>;
    var param_58: vec3<f32>;
    var share: f32;
    var local_11: f32;
    var local_12: f32;
    var param_59: MxcLobe;
    var param_60: vec3<f32>;
    var param_61: vec3<f32>;
    var param_62: MxcLobe;
    var param_63: f32;
    var local_13: f32;

    f_2 = vec3<f32>(0f, 0f, 0f);
    p_1 = 0f;
    k = 0i;
    loop {
        let _e195 = k;
        let _e197 = (*c_2).count;
        if (_e195 < _e197) {
            let _e199 = k;
            let _e202 = (*c_2).lobes[_e199];
            l_8 = _e202;
            let _e204 = l_8.weight;
            if all((_e204 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e208 = l_8.N;
            param_48 = _e208;
            let _e210 = l_8.T;
            param_49 = _e210;
            let _e211 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_48), (&param_49));
            frame_1 = _e211;
            let _e212 = frame_1;
            param_50 = _e212;
            let _e213 = (*wo_6);
            param_51 = _e213;
            let _e214 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_50), (&param_51));
            o_1 = _e214;
            let _e215 = frame_1;
            param_52 = _e215;
            let _e216 = (*wi_5);
            param_53 = _e216;
            let _e217 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_52), (&param_53));
            i_1 = _e217;
            fk = vec3<f32>(0f, 0f, 0f);
            pk = 0f;
            let _e218 = k;
            let _e221 = (*c_2).msPick[_e218];
            passes = select(1i, 2i, (_e221 > 0f));
            pass_ = 0i;
            loop {
                let _e224 = pass_;
                let _e225 = passes;
                if (_e224 < _e225) {
                    let _e227 = pass_;
                    shaped = (_e227 == 1i);
                    let _e229 = shaped;
                    if _e229 {
                        let _e231 = i_1[2u];
                        let _e233 = l_8;
                        param_54 = _e233;
                        param_55 = (_e231 < 0f);
                        let _e234 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_54), (&param_55));
                        local_7 = _e234;
                    } else {
                        let _e235 = l_8;
                        local_7 = _e235;
                    }
                    let _e236 = local_7;
                    m_4 = _e236;
                    let _e237 = shaped;
                    if _e237 {
                        let _e239 = i_1[2u];
                        if (_e239 > 0f) {
                            let _e241 = k;
                            let _e244 = (*c_2).msLobe[_e241];
                            local_9 = _e244;
                        } else {
                            let _e245 = k;
                            let _e248 = (*c_2).msLobeT[_e245];
                            local_9 = _e248;
                        }
                        let _e249 = local_9;
                        local_8 = _e249;
                    } else {
                        let _e251 = o_1[2u];
                        let _e253 = i_1[2u];
                        if ((_e251 * _e253) < 0f) {
                            let _e256 = k;
                            let _e259 = (*c_2).msT[_e256];
                            local_10 = vec3(_e259);
                        } else {
                            let _e261 = k;
                            let _e264 = (*c_2).ms[_e261];
                            local_10 = _e264;
                        }
                        let _e265 = local_10;
                        local_8 = _e265;
                    }
                    let _e266 = local_8;
                    scale = _e266;
                    let _e267 = scale;
                    let _e268 = m_4;
                    param_56 = _e268;
                    let _e269 = o_1;
                    param_57 = _e269;
                    let _e270 = i_1;
                    param_58 = _e270;
                    let _e271 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_56), (&param_57), (&param_58));
                    let _e273 = fk;
                    fk = (_e273 + (_e267 * _e271));
                    let _e275 = (*wantPdf);
                    if _e275 {
                        let _e276 = shaped;
                        if _e276 {
                            let _e277 = k;
                            let _e280 = (*c_2).msPick[_e277];
                            let _e282 = i_1[2u];
                            if (_e282 > 0f) {
                                let _e284 = k;
                                let _e287 = (*c_2).msSplit[_e284];
                                local_12 = _e287;
                            } else {
                                let _e288 = k;
                                let _e291 = (*c_2).msSplit[_e288];
                                local_12 = (1f - _e291);
                            }
                            let _e293 = local_12;
                            local_11 = (_e280 * _e293);
                        } else {
                            let _e295 = k;
                            let _e298 = (*c_2).msPick[_e295];
                            local_11 = (1f - _e298);
                        }
                        let _e300 = local_11;
                        share = _e300;
                        let _e301 = share;
                        let _e302 = m_4;
                        param_59 = _e302;
                        let _e303 = o_1;
                        param_60 = _e303;
                        let _e304 = i_1;
                        param_61 = _e304;
                        let _e305 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_59), (&param_60), (&param_61));
                        let _e307 = pk;
                        pk = (_e307 + (_e301 * _e305));
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e309 = pass_;
                    pass_ = (_e309 + 1i);
                }
            }
            let _e312 = l_8.weight;
            let _e314 = i_1[2u];
            let _e316 = l_8;
            param_62 = _e316;
            param_63 = abs(_e314);
            let _e317 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_62), (&param_63));
            let _e319 = fk;
            let _e321 = f_2;
            f_2 = (_e321 + ((_e312 * _e317) * _e319));
            let _e323 = (*wantPdf);
            if _e323 {
                let _e324 = k;
                let _e327 = (*c_2).choice[_e324];
                let _e328 = pk;
                let _e330 = p_1;
                p_1 = (_e330 + (_e327 * _e328));
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e332 = k;
            k = (_e332 + 1i);
        }
    }
    let _e335 = (*c_2).choiceTotal;
    if (_e335 > 0f) {
        let _e337 = p_1;
        let _e339 = (*c_2).choiceTotal;
        local_13 = (_e337 / _e339);
    } else {
        local_13 = 0f;
    }
    let _e341 = local_13;
    (*pdf) = _e341;
    let _e342 = f_2;
    return _e342;
}

fn mxc_env_to_world_u0028_vf3_u003b_f1_u003b(m_5: ptr<function, vec3<f32>>, angle: ptr<function, f32>) -> vec3<f32> {
    var c_3: f32;
    var s_3: f32;

    let _e156 = (*angle);
    c_3 = cos(_e156);
    let _e158 = (*angle);
    s_3 = sin(_e158);
    let _e160 = c_3;
    let _e162 = (*m_5)[0u];
    let _e164 = s_3;
    let _e166 = (*m_5)[2u];
    let _e170 = (*m_5)[1u];
    let _e171 = s_3;
    let _e174 = (*m_5)[0u];
    let _e176 = c_3;
    let _e178 = (*m_5)[2u];
    return vec3<f32>(((_e160 * _e162) + (_e164 * _e166)), _e170, ((-(_e171) * _e174) + (_e176 * _e178)));
}

fn mxc_safe_sqrt_u0028_f1_u003b(x_1: ptr<function, f32>) -> f32 {
    let _e153 = (*x_1);
    return sqrt(max(_e153, 0f));
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
    var param_64: f32;

    let _e167 = unnamed.mxc_env_size;
    size = max(_e167.xy, vec2<u32>(1u, 1u));
    let _e171 = size[0u];
    let _e173 = size[1u];
    n = (_e171 * _e173);
    let _e176 = (*u)[0u];
    let _e177 = n;
    let _e181 = n;
    k_1 = min(u32((_e176 * f32(_e177))), (_e181 - 1u));
    let _e184 = k_1;
    let _e187 = unnamed.mxc_env_cells[_e184];
    cell = _e187;
    let _e189 = (*u)[1u];
    let _e191 = cell[0u];
    if (_e189 >= _e191) {
        let _e194 = cell[1u];
        let _e196 = n;
        k_1 = min(bitcast<u32>(_e194), (_e196 - 1u));
    }
    let _e199 = k_1;
    let _e203 = unnamed.mxc_env_cells[_e199][2u];
    (*pdf_1) = _e203;
    let _e204 = k_1;
    let _e206 = size[0u];
    i_2 = (_e204 % _e206);
    let _e208 = k_1;
    let _e210 = size[0u];
    j = (_e208 / _e210);
    let _e212 = i_2;
    let _e215 = (*u)[2u];
    let _e218 = size[0u];
    phi = (6.2831855f * (((f32(_e212) + _e215) / f32(_e218)) - 0.5f));
    let _e223 = j;
    let _e227 = size[1u];
    y0_ = cos(((3.1415927f * f32(_e223)) / f32(_e227)));
    let _e231 = j;
    let _e236 = size[1u];
    y1_ = cos(((3.1415927f * f32((_e231 + 1u))) / f32(_e236)));
    let _e240 = y0_;
    let _e241 = y1_;
    let _e243 = (*u)[3u];
    y = mix(_e240, _e241, _e243);
    let _e245 = y;
    let _e246 = y;
    param_64 = (1f - (_e245 * _e246));
    let _e249 = mxc_safe_sqrt_u0028_f1_u003b((&param_64));
    r = _e249;
    let _e250 = r;
    let _e251 = phi;
    let _e254 = y;
    let _e255 = r;
    let _e257 = phi;
    return vec3<f32>((_e250 * sin(_e251)), _e254, (-(_e255) * cos(_e257)));
}

fn mxc_power_heuristic_u0028_f1_u003b_f1_u003b(a_2: ptr<function, f32>, b_1: ptr<function, f32>) -> f32 {
    var a2_1: f32;
    var b2_: f32;
    var local_14: f32;

    let _e157 = (*a_2);
    let _e158 = (*a_2);
    a2_1 = (_e157 * _e158);
    let _e160 = (*b_1);
    let _e161 = (*b_1);
    b2_ = (_e160 * _e161);
    let _e163 = a2_1;
    let _e164 = b2_;
    if ((_e163 + _e164) > 0f) {
        let _e167 = a2_1;
        let _e168 = a2_1;
        let _e169 = b2_;
        local_14 = (_e167 / (_e168 + _e169));
    } else {
        local_14 = 0f;
    }
    let _e172 = local_14;
    return _e172;
}

fn mxc_env_uv_u0028_vf3_u003b(d_1: ptr<function, vec3<f32>>) -> vec2<f32> {
    var u_1: f32;
    var local_15: f32;
    var v_3: f32;

    let _e157 = (*d_1)[0u];
    let _e160 = (*d_1)[2u];
    if ((abs(_e157) + abs(_e160)) > 0.000000000001f) {
        let _e165 = (*d_1)[0u];
        let _e167 = (*d_1)[2u];
        local_15 = (0.5f + (atan2(_e165, -(_e167)) * 0.15915494f));
    } else {
        local_15 = 0.5f;
    }
    let _e172 = local_15;
    u_1 = _e172;
    let _e173 = (*d_1);
    let _e177 = (*d_1)[1u];
    v_3 = (atan2(length(_e173.xz), _e177) * 0.31830987f);
    let _e180 = u_1;
    let _e181 = v_3;
    return vec2<f32>(_e180, _e181);
}

fn mxc_env_cell_u0028_vf3_u003b(d_2: ptr<function, vec3<f32>>) -> u32 {
    var uv: vec2<f32>;
    var param_65: vec3<f32>;
    var size_1: vec2<u32>;
    var i_3: u32;
    var j_1: u32;

    let _e158 = (*d_2);
    param_65 = _e158;
    let _e159 = mxc_env_uv_u0028_vf3_u003b((&param_65));
    uv = _e159;
    let _e161 = unnamed.mxc_env_size;
    size_1 = max(_e161.xy, vec2<u32>(1u, 1u));
    let _e165 = uv[0u];
    let _e168 = size_1[0u];
    let _e173 = size_1[0u];
    i_3 = min(u32((max(_e165, 0f) * f32(_e168))), (_e173 - 1u));
    let _e177 = uv[1u];
    let _e180 = size_1[1u];
    let _e185 = size_1[1u];
    j_1 = min(u32((max(_e177, 0f) * f32(_e180))), (_e185 - 1u));
    let _e188 = j_1;
    let _e190 = size_1[0u];
    let _e192 = i_3;
    return ((_e188 * _e190) + _e192);
}

fn mxc_env_pdf_u0028_vf3_u003b(d_3: ptr<function, vec3<f32>>) -> f32 {
    var param_66: vec3<f32>;

    let _e154 = (*d_3);
    param_66 = _e154;
    let _e155 = mxc_env_cell_u0028_vf3_u003b((&param_66));
    let _e159 = unnamed.mxc_env_cells[_e155][2u];
    return _e159;
}

fn mxc_env_to_map_u0028_vf3_u003b_f1_u003b(w: ptr<function, vec3<f32>>, angle_1: ptr<function, f32>) -> vec3<f32> {
    var c_4: f32;
    var s_4: f32;

    let _e156 = (*angle_1);
    c_4 = cos(_e156);
    let _e158 = (*angle_1);
    s_4 = sin(_e158);
    let _e160 = c_4;
    let _e162 = (*w)[0u];
    let _e164 = s_4;
    let _e166 = (*w)[2u];
    let _e170 = (*w)[1u];
    let _e171 = s_4;
    let _e173 = (*w)[0u];
    let _e175 = c_4;
    let _e177 = (*w)[2u];
    return vec3<f32>(((_e160 * _e162) - (_e164 * _e166)), _e170, ((_e171 * _e173) + (_e175 * _e177)));
}

fn mxc_env_lookup_u0028_vf3_u003b(d_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_67: vec3<f32>;

    let _e154 = (*d_4);
    param_67 = _e154;
    let _e155 = mxc_env_uv_u0028_vf3_u003b((&param_67));
    let _e156 = textureSampleLevel(mxc_env_radiance_texture, mxc_env_radiance_sampler, _e155, 0f);
    return _e156.xyz;
}

fn mxc_sky_u0028_vf3_u003b(d_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var y_1: f32;
    var horizon: vec3<f32>;
    var zenith: vec3<f32>;
    var ground: vec3<f32>;

    let _e158 = (*d_5)[1u];
    y_1 = clamp(_e158, -1f, 1f);
    horizon = vec3<f32>(1f, 0.96f, 0.9f);
    zenith = vec3<f32>(0.3f, 0.5f, 0.95f);
    ground = vec3<f32>(0.16f, 0.145f, 0.13f);
    let _e160 = y_1;
    if (_e160 >= 0f) {
        let _e162 = horizon;
        let _e163 = zenith;
        let _e164 = y_1;
        return mix(_e162, _e163, vec3(sqrt(_e164)));
    }
    let _e168 = horizon;
    let _e169 = ground;
    let _e170 = y_1;
    return mix(_e168, _e169, vec3(sqrt(-(_e170))));
}

fn mxc_environment_code_u0028_() -> i32 {
    var local_16: i32;

    if false {
        local_16 = MXC_ENVIRONMENT;
    } else {
        let _e155 = mxc_view.counts[1u];
        local_16 = _e155;
    }
    let _e156 = local_16;
    return _e156;
}

fn mxc_environment_u0028_vf3_u003b(d_6: ptr<function, vec3<f32>>) -> vec3<f32> {
    var code: i32;
    var param_68: vec3<f32>;
    var param_69: vec3<f32>;
    var param_70: f32;
    var param_71: vec3<f32>;

    let _e158 = mxc_environment_code_u0028_();
    code = _e158;
    let _e159 = code;
    if (_e159 == 1i) {
        let _e163 = mxc_view.environment[0u];
        return vec3(_e163);
    }
    let _e165 = code;
    if (_e165 == 2i) {
        let _e169 = mxc_view.environment[0u];
        let _e170 = (*d_6);
        param_68 = _e170;
        let _e171 = mxc_sky_u0028_vf3_u003b((&param_68));
        return (_e171 * _e169);
    }
    let _e173 = code;
    if (_e173 == 3i) {
        let _e177 = mxc_view.environment[0u];
        let _e178 = (*d_6);
        param_69 = _e178;
        let _e181 = mxc_view.environment[2u];
        param_70 = _e181;
        let _e182 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_69), (&param_70));
        param_71 = _e182;
        let _e183 = mxc_env_lookup_u0028_vf3_u003b((&param_71));
        return (_e183 * _e177);
    }
    return vec3<f32>(0f, 0f, 0f);
}

fn mxc_exit_direction_u0028_vf3_u003b_vf3_u003b(d_7: ptr<function, vec3<f32>>, t_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var axis: vec3<f32>;
    var s_5: f32;
    var c_5: f32;

    let _e157 = (*d_7);
    let _e158 = (*t_2);
    axis = cross(_e157, _e158);
    let _e160 = axis;
    s_5 = length(_e160);
    let _e162 = s_5;
    if (_e162 < 0.000001f) {
        let _e164 = (*t_2);
        return _e164;
    }
    let _e165 = s_5;
    let _e166 = axis;
    axis = (_e166 / vec3(_e165));
    let _e169 = (*d_7);
    let _e170 = (*t_2);
    c_5 = dot(_e169, _e170);
    let _e172 = (*t_2);
    let _e173 = c_5;
    let _e175 = axis;
    let _e176 = (*t_2);
    let _e178 = s_5;
    let _e181 = axis;
    let _e182 = axis;
    let _e183 = (*t_2);
    let _e186 = c_5;
    return (((_e172 * _e173) + (cross(_e175, _e176) * _e178)) + ((_e181 * dot(_e182, _e183)) * (1f - _e186)));
}

fn mxc_to_world_u0028_mf33_u003b_vf3_u003b(frame_2: ptr<function, mat3x3<f32>>, v_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e155 = (*frame_2)[0];
    let _e157 = (*v_4)[0u];
    let _e160 = (*frame_2)[1];
    let _e162 = (*v_4)[1u];
    let _e166 = (*frame_2)[2];
    let _e168 = (*v_4)[2u];
    return (((_e155 * _e157) + (_e160 * _e162)) + (_e166 * _e168));
}

fn mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b(wo_7: ptr<function, vec3<f32>>, alpha_7: ptr<function, vec2<f32>>, u_2: ptr<function, vec2<f32>>) -> vec3<f32> {
    var param_72: vec2<f32>;
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
    var param_73: f32;
    var nh: vec3<f32>;
    var param_74: f32;

    let _e169 = (*alpha_7);
    param_72 = _e169;
    let _e170 = mxc_rough_alpha_u0028_vf2_u003b((&param_72));
    (*alpha_7) = _e170;
    let _e172 = (*alpha_7)[0u];
    let _e174 = (*wo_7)[0u];
    let _e177 = (*alpha_7)[1u];
    let _e179 = (*wo_7)[1u];
    let _e182 = (*wo_7)[2u];
    vh = normalize(vec3<f32>((_e172 * _e174), (_e177 * _e179), _e182));
    let _e186 = vh[0u];
    let _e188 = vh[0u];
    let _e191 = vh[1u];
    let _e193 = vh[1u];
    lensq = ((_e186 * _e188) + (_e191 * _e193));
    let _e196 = lensq;
    if (_e196 > 0f) {
        let _e199 = vh[1u];
        let _e202 = vh[0u];
        let _e204 = lensq;
        local_17 = (vec3<f32>(-(_e199), _e202, 0f) * inverseSqrt(_e204));
    } else {
        local_17 = vec3<f32>(1f, 0f, 0f);
    }
    let _e207 = local_17;
    t1_ = _e207;
    let _e208 = vh;
    let _e209 = t1_;
    t2_ = cross(_e208, _e209);
    let _e212 = (*u_2)[0u];
    r_1 = sqrt(_e212);
    let _e215 = (*u_2)[1u];
    phi_1 = (6.2831855f * _e215);
    let _e217 = r_1;
    let _e218 = phi_1;
    p1_ = (_e217 * cos(_e218));
    let _e221 = r_1;
    let _e222 = phi_1;
    p2_ = (_e221 * sin(_e222));
    let _e226 = vh[2u];
    s_6 = (0.5f * (1f + _e226));
    let _e229 = s_6;
    let _e231 = p1_;
    let _e232 = p1_;
    param_73 = (1f - (_e231 * _e232));
    let _e235 = mxc_safe_sqrt_u0028_f1_u003b((&param_73));
    let _e237 = s_6;
    let _e238 = p2_;
    p2_ = (((1f - _e229) * _e235) + (_e237 * _e238));
    let _e241 = p1_;
    let _e242 = t1_;
    let _e244 = p2_;
    let _e245 = t2_;
    let _e248 = p1_;
    let _e249 = p1_;
    let _e252 = p2_;
    let _e253 = p2_;
    param_74 = ((1f - (_e248 * _e249)) - (_e252 * _e253));
    let _e256 = mxc_safe_sqrt_u0028_f1_u003b((&param_74));
    let _e257 = vh;
    nh = (((_e242 * _e241) + (_e245 * _e244)) + (_e257 * _e256));
    let _e261 = (*alpha_7)[0u];
    let _e263 = nh[0u];
    let _e266 = (*alpha_7)[1u];
    let _e268 = nh[1u];
    let _e271 = nh[2u];
    return normalize(vec3<f32>((_e261 * _e263), (_e266 * _e268), max(_e271, 0f)));
}

fn mxc_sample_cosine_u0028_vf2_u003b(u_3: ptr<function, vec2<f32>>) -> vec3<f32> {
    var r_2: f32;
    var phi_2: f32;
    var param_75: f32;

    let _e157 = (*u_3)[0u];
    r_2 = sqrt(_e157);
    let _e160 = (*u_3)[1u];
    phi_2 = (6.2831855f * _e160);
    let _e162 = r_2;
    let _e163 = phi_2;
    let _e166 = r_2;
    let _e167 = phi_2;
    let _e171 = (*u_3)[0u];
    param_75 = (1f - _e171);
    let _e173 = mxc_safe_sqrt_u0028_f1_u003b((&param_75));
    return vec3<f32>((_e162 * cos(_e163)), (_e166 * sin(_e167)), _e173);
}

fn mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_9: ptr<function, MxcLobe>, wo_8: ptr<function, vec3<f32>>, u_4: ptr<function, vec3<f32>>) -> MxcLobeSample {
    var s_7: MxcLobeSample;
    var above_3: bool;
    var o_2: vec3<f32>;
    var local_18: vec3<f32>;
    var delta: bool;
    var param_76: vec2<f32>;
    var m_6: vec3<f32>;
    var local_19: vec3<f32>;
    var param_77: vec3<f32>;
    var param_78: vec2<f32>;
    var param_79: vec2<f32>;
    var hm: f32;
    var transmits: bool;
    var param_80: MxcLobe;
    var reflects: bool;
    var f_3: vec3<f32>;
    var param_81: MxcLobe;
    var param_82: f32;
    var param_83: bool;
    var fr_1: f32;
    var local_20: f32;
    var param_84: vec3<f32>;
    var pReflect: f32;
    var local_21: f32;
    var i_4: vec3<f32>;
    var local_22: vec3<f32>;
    var tint: vec3<f32>;
    var local_23: vec3<f32>;
    var local_24: vec3<f32>;
    var param_85: MxcLobe;
    var param_86: vec3<f32>;
    var param_87: vec3<f32>;
    var param_88: MxcLobe;
    var param_89: vec3<f32>;
    var param_90: vec3<f32>;
    var param_91: vec2<f32>;
    var param_92: MxcLobe;
    var param_93: vec3<f32>;
    var param_94: vec3<f32>;
    var param_95: MxcLobe;
    var param_96: vec3<f32>;
    var param_97: vec3<f32>;
    var phi_3063_: bool;
    var phi_3068_: bool;
    var phi_3079_: bool;

    s_7.valid = false;
    s_7.delta = false;
    s_7.pdf = 0f;
    s_7.value = vec3<f32>(0f, 0f, 0f);
    s_7.wi = vec3<f32>(0f, 0f, 1f);
    let _e203 = (*l_9).kind;
    switch _e203 {
        case 2, 3, 1: {
            let _e230 = (*wo_8)[2u];
            above_3 = (_e230 > 0f);
            let _e232 = above_3;
            if _e232 {
                let _e233 = (*wo_8);
                local_18 = _e233;
            } else {
                let _e234 = (*wo_8);
                local_18 = -(_e234);
            }
            let _e236 = local_18;
            o_2 = _e236;
            let _e238 = o_2[2u];
            if (_e238 <= 0f) {
                let _e240 = s_7;
                return _e240;
            }
            let _e242 = (*l_9).alpha;
            param_76 = _e242;
            let _e243 = mxc_is_delta_u0028_vf2_u003b((&param_76));
            delta = _e243;
            let _e244 = delta;
            if _e244 {
                local_19 = vec3<f32>(0f, 0f, 1f);
            } else {
                let _e245 = o_2;
                param_77 = _e245;
                let _e247 = (*l_9).alpha;
                param_78 = _e247;
                let _e248 = (*u_4);
                param_79 = _e248.xy;
                let _e250 = mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b((&param_77), (&param_78), (&param_79));
                local_19 = _e250;
            }
            let _e251 = local_19;
            m_6 = _e251;
            let _e252 = o_2;
            let _e253 = m_6;
            hm = dot(_e252, _e253);
            let _e256 = (*l_9).kind;
            let _e257 = (_e256 == 1i);
            phi_3063_ = _e257;
            if !(_e257) {
                let _e260 = (*l_9).kind;
                phi_3063_ = (_e260 == 3i);
            }
            let _e263 = phi_3063_;
            phi_3068_ = _e263;
            if _e263 {
                let _e264 = (*l_9);
                param_80 = _e264;
                let _e265 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_80));
                phi_3068_ = _e265;
            }
            let _e267 = phi_3068_;
            transmits = _e267;
            let _e269 = (*l_9).kind;
            let _e270 = (_e269 == 2i);
            phi_3079_ = _e270;
            if !(_e270) {
                let _e273 = (*l_9).mode;
                phi_3079_ = ((_e273 & 1i) != 0i);
            }
            let _e277 = phi_3079_;
            reflects = _e277;
            let _e278 = hm;
            let _e280 = (*l_9);
            param_81 = _e280;
            param_82 = max(_e278, 0f);
            let _e281 = above_3;
            param_83 = _e281;
            let _e282 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_81), (&param_82), (&param_83));
            f_3 = _e282;
            let _e283 = transmits;
            if _e283 {
                let _e284 = f_3;
                param_84 = _e284;
                let _e285 = mxc_mean_u0028_vf3_u003b((&param_84));
                local_20 = _e285;
            } else {
                local_20 = 1f;
            }
            let _e286 = local_20;
            fr_1 = _e286;
            let _e287 = transmits;
            if _e287 {
                let _e288 = reflects;
                let _e289 = fr_1;
                local_21 = select(0f, _e289, _e288);
            } else {
                local_21 = 1f;
            }
            let _e291 = local_21;
            pReflect = _e291;
            let _e293 = (*u_4)[2u];
            let _e294 = pReflect;
            if (_e293 < _e294) {
                let _e296 = o_2;
                let _e298 = m_6;
                i_4 = reflect(-(_e296), _e298);
                let _e301 = i_4[2u];
                if (_e301 <= 0f) {
                    let _e303 = s_7;
                    return _e303;
                }
                let _e304 = above_3;
                if _e304 {
                    let _e305 = i_4;
                    local_22 = _e305;
                } else {
                    let _e306 = i_4;
                    local_22 = -(_e306);
                }
                let _e308 = local_22;
                s_7.wi = _e308;
                let _e310 = delta;
                s_7.delta = _e310;
                let _e312 = delta;
                if _e312 {
                    let _e314 = (*l_9).kind;
                    if (_e314 == 1i) {
                        let _e316 = above_3;
                        if _e316 {
                            let _e318 = (*l_9).c0_;
                            local_24 = _e318;
                        } else {
                            local_24 = vec3<f32>(1f, 1f, 1f);
                        }
                        let _e319 = local_24;
                        local_23 = _e319;
                    } else {
                        local_23 = vec3<f32>(1f, 1f, 1f);
                    }
                    let _e320 = local_23;
                    tint = _e320;
                    let _e321 = f_3;
                    let _e322 = tint;
                    s_7.value = (_e321 * _e322);
                    let _e325 = pReflect;
                    s_7.pdf = _e325;
                } else {
                    let _e327 = (*l_9);
                    param_85 = _e327;
                    let _e328 = (*wo_8);
                    param_86 = _e328;
                    let _e330 = s_7.wi;
                    param_87 = _e330;
                    let _e331 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_85), (&param_86), (&param_87));
                    s_7.value = _e331;
                    let _e333 = (*l_9);
                    param_88 = _e333;
                    let _e334 = (*wo_8);
                    param_89 = _e334;
                    let _e336 = s_7.wi;
                    param_90 = _e336;
                    let _e337 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_88), (&param_89), (&param_90));
                    s_7.pdf = _e337;
                }
                let _e340 = s_7.pdf;
                s_7.valid = (_e340 > 0f);
                let _e343 = s_7;
                return _e343;
            }
            let _e344 = s_7;
            return _e344;
        }
        default: {
            let _e205 = (*wo_8)[2u];
            if (_e205 <= 0f) {
                let _e207 = s_7;
                return _e207;
            }
            let _e208 = (*u_4);
            param_91 = _e208.xy;
            let _e210 = mxc_sample_cosine_u0028_vf2_u003b((&param_91));
            s_7.wi = _e210;
            let _e212 = (*l_9);
            param_92 = _e212;
            let _e213 = (*wo_8);
            param_93 = _e213;
            let _e215 = s_7.wi;
            param_94 = _e215;
            let _e216 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_92), (&param_93), (&param_94));
            s_7.value = _e216;
            let _e218 = (*l_9);
            param_95 = _e218;
            let _e219 = (*wo_8);
            param_96 = _e219;
            let _e221 = s_7.wi;
            param_97 = _e221;
            let _e222 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_95), (&param_96), (&param_97));
            s_7.pdf = _e222;
            let _e225 = s_7.pdf;
            s_7.valid = (_e225 > 0f);
            let _e228 = s_7;
            return _e228;
        }
    }
}

fn mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b(c_6: ptr<function, MxcClosure>, wo_9: ptr<function, vec3<f32>>, u_5: ptr<function, vec3<f32>>) -> MxcSample {
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
    var l_10: MxcLobe;
    var frame_3: mat3x3<f32>;
    var param_98: vec3<f32>;
    var param_99: vec3<f32>;
    var o_3: vec3<f32>;
    var param_100: mat3x3<f32>;
    var param_101: vec3<f32>;
    var q: f32;
    var shaped_1: bool;
    var reflected: bool;
    var v_5: f32;
    var split: f32;
    var local_25: f32;
    var m_7: MxcLobe;
    var local_26: MxcLobe;
    var param_102: MxcLobe;
    var param_103: bool;
    var ls: MxcLobeSample;
    var param_104: MxcLobe;
    var param_105: vec3<f32>;
    var param_106: vec3<f32>;
    var param_107: mat3x3<f32>;
    var param_108: vec3<f32>;
    var param_109: MxcLobe;
    var param_110: f32;

    s_8.valid = false;
    s_8.delta = false;
    s_8.evaluate = false;
    s_8.pdf = 0f;
    s_8.weight = vec3<f32>(0f, 0f, 0f);
    let _e196 = (*wo_9);
    s_8.wi = _e196;
    let _e199 = (*c_6).choiceTotal;
    total = _e199;
    let _e201 = (*c_6).count;
    let _e203 = total;
    if ((_e201 == 0i) || (_e203 <= 0f)) {
        let _e206 = s_8;
        return _e206;
    }
    let _e208 = (*u_5)[2u];
    let _e209 = total;
    x_2 = (_e208 * _e209);
    chosen = -1i;
    before = 0f;
    p_2 = 0f;
    lastBefore = 0f;
    last = -1i;
    k_2 = 0i;
    loop {
        let _e211 = k_2;
        let _e213 = (*c_6).count;
        if (_e211 < _e213) {
            let _e215 = k_2;
            let _e218 = (*c_6).choice[_e215];
            pk_1 = _e218;
            let _e219 = pk_1;
            if (_e219 <= 0f) {
                continue;
            }
            let _e221 = x_2;
            let _e222 = before;
            let _e223 = pk_1;
            if (_e221 < (_e222 + _e223)) {
                let _e226 = k_2;
                chosen = _e226;
                let _e227 = pk_1;
                p_2 = _e227;
                break;
            }
            let _e228 = k_2;
            last = _e228;
            let _e229 = before;
            lastBefore = _e229;
            let _e230 = pk_1;
            let _e231 = before;
            before = (_e231 + _e230);
            continue;
        } else {
            break;
        }
        continuing {
            let _e233 = k_2;
            k_2 = (_e233 + 1i);
        }
    }
    let _e235 = chosen;
    if (_e235 < 0i) {
        let _e237 = last;
        chosen = max(_e237, 0i);
        let _e239 = chosen;
        let _e242 = (*c_6).choice[_e239];
        p_2 = _e242;
        let _e243 = lastBefore;
        before = _e243;
    }
    let _e244 = p_2;
    if (_e244 <= 0f) {
        let _e246 = s_8;
        return _e246;
    }
    let _e247 = x_2;
    let _e248 = before;
    let _e250 = p_2;
    uz = clamp(((_e247 - _e248) / _e250), 0f, 0.99999994f);
    let _e253 = chosen;
    let _e256 = (*c_6).lobes[_e253];
    l_10 = _e256;
    let _e258 = l_10.N;
    param_98 = _e258;
    let _e260 = l_10.T;
    param_99 = _e260;
    let _e261 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_98), (&param_99));
    frame_3 = _e261;
    let _e262 = frame_3;
    param_100 = _e262;
    let _e263 = (*wo_9);
    param_101 = _e263;
    let _e264 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_100), (&param_101));
    o_3 = _e264;
    let _e265 = chosen;
    let _e268 = (*c_6).msPick[_e265];
    q = _e268;
    let _e269 = uz;
    let _e270 = q;
    shaped_1 = (_e269 < _e270);
    reflected = true;
    let _e272 = shaped_1;
    if _e272 {
        let _e273 = uz;
        let _e274 = q;
        v_5 = (_e273 / _e274);
        let _e276 = chosen;
        let _e279 = (*c_6).msSplit[_e276];
        split = _e279;
        let _e280 = v_5;
        let _e281 = split;
        reflected = (_e280 < _e281);
        let _e283 = reflected;
        if _e283 {
            let _e284 = v_5;
            let _e285 = split;
            local_25 = (_e284 / max(_e285, 0.000001f));
        } else {
            let _e288 = v_5;
            let _e289 = split;
            let _e291 = split;
            local_25 = ((_e288 - _e289) / max((1f - _e291), 0.000001f));
        }
        let _e295 = local_25;
        uz = _e295;
    } else {
        let _e296 = uz;
        let _e297 = q;
        let _e299 = q;
        uz = ((_e296 - _e297) / (1f - _e299));
    }
    let _e302 = shaped_1;
    if _e302 {
        let _e303 = reflected;
        let _e305 = l_10;
        param_102 = _e305;
        param_103 = !(_e303);
        let _e306 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_102), (&param_103));
        local_26 = _e306;
    } else {
        let _e307 = l_10;
        local_26 = _e307;
    }
    let _e308 = local_26;
    m_7 = _e308;
    let _e309 = (*u_5);
    let _e310 = _e309.xy;
    let _e311 = uz;
    let _e316 = m_7;
    param_104 = _e316;
    let _e317 = o_3;
    param_105 = _e317;
    param_106 = vec3<f32>(_e310.x, _e310.y, min(_e311, 0.99999994f));
    let _e318 = mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_104), (&param_105), (&param_106));
    ls = _e318;
    let _e320 = ls.valid;
    if !(_e320) {
        let _e322 = s_8;
        return _e322;
    }
    let _e323 = frame_3;
    param_107 = _e323;
    let _e325 = ls.wi;
    param_108 = _e325;
    let _e326 = mxc_to_world_u0028_mf33_u003b_vf3_u003b((&param_107), (&param_108));
    s_8.wi = _e326;
    let _e329 = ls.delta;
    if _e329 {
        s_8.delta = true;
        let _e332 = ls.pdf;
        let _e333 = p_2;
        let _e335 = total;
        s_8.pdf = ((_e332 * _e333) / _e335);
        let _e339 = l_10.weight;
        let _e340 = chosen;
        let _e343 = (*c_6).ms[_e340];
        let _e347 = ls.wi[2u];
        let _e349 = l_10;
        param_109 = _e349;
        param_110 = abs(_e347);
        let _e350 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_109), (&param_110));
        let _e353 = ls.value;
        let _e356 = s_8.pdf;
        s_8.weight = ((((_e339 * _e343) * _e350) * _e353) / vec3(_e356));
        let _e361 = s_8.pdf;
        s_8.valid = (_e361 > 0f);
        let _e364 = s_8;
        return _e364;
    }
    s_8.evaluate = true;
    s_8.valid = true;
    let _e367 = s_8;
    return _e367;
}

fn mxc_radical_inverse_u0028_u1_u003b_u1_u003b(i_5: ptr<function, u32>, base: ptr<function, u32>) -> f32 {
    var inv: f32;
    var f_4: f32;
    var r_3: f32;

    let _e157 = (*base);
    if (_e157 == 2u) {
        let _e159 = (*i_5);
        return (f32((reverseBits(_e159) >> bitcast<u32>(8i))) * 0.000000059604645f);
    }
    let _e165 = (*base);
    inv = (1f / f32(_e165));
    let _e168 = inv;
    f_4 = _e168;
    r_3 = 0f;
    loop {
        let _e169 = (*i_5);
        if (_e169 > 0u) {
            let _e171 = f_4;
            let _e172 = (*i_5);
            let _e173 = (*base);
            let _e177 = r_3;
            r_3 = (_e177 + (_e171 * f32((_e172 % _e173))));
            let _e179 = inv;
            let _e180 = f_4;
            f_4 = (_e180 * _e179);
            continue;
        } else {
            break;
        }
        continuing {
            let _e182 = (*base);
            let _e183 = (*i_5);
            (*i_5) = (_e183 / _e182);
        }
    }
    let _e185 = r_3;
    return min(_e185, 0.99999994f);
}

fn mxc_pcg_u0028_u1_u003b(v_6: ptr<function, u32>) -> u32 {
    var state: u32;
    var word: u32;

    let _e155 = (*v_6);
    state = ((_e155 * 747796405u) + 2891336453u);
    let _e158 = state;
    let _e159 = state;
    let _e165 = state;
    word = (((_e158 >> bitcast<u32>(((_e159 >> bitcast<u32>(28u)) + 4u))) ^ _e165) * 277803737u);
    let _e168 = word;
    let _e171 = word;
    return ((_e168 >> bitcast<u32>(22u)) ^ _e171);
}

fn mxc_uniform_u0028_u1_u003b(seed: ptr<function, u32>) -> f32 {
    var param_111: u32;

    let _e154 = (*seed);
    param_111 = _e154;
    let _e155 = mxc_pcg_u0028_u1_u003b((&param_111));
    (*seed) = _e155;
    let _e156 = (*seed);
    return (f32((_e156 >> bitcast<u32>(8i))) * 0.000000059604645f);
}

fn mxc_light_kinds_u0028_() -> i32 {
    return 7i;
}

fn mxc_light_count_u0028_() -> i32 {
    var local_27: i32;

    if false {
        local_27 = MXC_LIGHT_COUNT;
    } else {
        let _e155 = mxc_view.counts[0u];
        local_27 = _e155;
    }
    let _e156 = local_27;
    return min(_e156, 8i);
}

fn mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b(mu_1: ptr<function, f32>, x_3: ptr<function, f32>, firstRow: ptr<function, f32>) -> vec4<f32> {
    var t_3: vec2<f32>;

    let _e156 = (*mu_1);
    let _e159 = (*x_3);
    t_3 = ((vec2<f32>(sqrt(clamp(_e156, 0f, 1f)), clamp(_e159, 0f, 1f)) * 31f) + vec2(0.5f));
    let _e166 = t_3[0u];
    let _e168 = (*firstRow);
    let _e170 = t_3[1u];
    let _e174 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, vec2<f32>((_e166 / 32f), ((_e168 + _e170) / 2070f)), 0f);
    return _e174;
}

fn mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b(mu_2: ptr<function, f32>, alpha_8: ptr<function, f32>, e: ptr<function, f32>) -> vec4<f32> {
    var s_9: f32;
    var s0_: f32;
    var x_4: f32;
    var a_3: vec4<f32>;
    var param_112: f32;
    var param_113: f32;
    var param_114: f32;
    var b_2: vec4<f32>;
    var param_115: f32;
    var param_116: f32;
    var param_117: f32;

    let _e166 = (*e);
    s_9 = (sqrt(clamp((0.5f * (_e166 - 1f)), 0f, 1f)) * 31f);
    let _e172 = s_9;
    s0_ = min(floor(_e172), 30f);
    let _e175 = (*alpha_8);
    x_4 = sqrt(max(_e175, 0f));
    let _e178 = s0_;
    let _e181 = (*mu_2);
    param_112 = _e181;
    let _e182 = x_4;
    param_113 = _e182;
    param_114 = (32f * (1f + _e178));
    let _e183 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_112), (&param_113), (&param_114));
    a_3 = _e183;
    let _e184 = s0_;
    let _e187 = (*mu_2);
    param_115 = _e187;
    let _e188 = x_4;
    param_116 = _e188;
    param_117 = (32f * (2f + _e184));
    let _e189 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_115), (&param_116), (&param_117));
    b_2 = _e189;
    let _e190 = a_3;
    let _e191 = b_2;
    let _e192 = s_9;
    let _e193 = s0_;
    return mix(_e190, _e191, vec4((_e192 - _e193)));
}

fn mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b(mu_3: ptr<function, f32>, alpha_9: ptr<function, f32>, eta_1: ptr<function, f32>) -> f32 {
    var param_118: f32;
    var param_119: f32;
    var param_120: f32;
    var param_121: f32;
    var param_122: f32;
    var param_123: f32;

    let _e161 = (*eta_1);
    if (_e161 >= 1f) {
        let _e163 = (*mu_3);
        param_118 = _e163;
        let _e164 = (*alpha_9);
        param_119 = _e164;
        let _e165 = (*eta_1);
        param_120 = _e165;
        let _e166 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_118), (&param_119), (&param_120));
        return _e166.y;
    }
    let _e168 = (*eta_1);
    let _e171 = (*mu_3);
    param_121 = _e171;
    let _e172 = (*alpha_9);
    param_122 = _e172;
    param_123 = (1f / max(_e168, 0.001f));
    let _e173 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_121), (&param_122), (&param_123));
    return _e173.z;
}

fn mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b(mu_4: ptr<function, f32>, alpha_10: ptr<function, f32>, eta_2: ptr<function, f32>) -> f32 {
    var e_1: f32;
    var local_28: f32;
    var param_124: f32;
    var param_125: f32;
    var param_126: f32;

    let _e160 = (*eta_2);
    if (_e160 >= 1f) {
        let _e162 = (*eta_2);
        local_28 = _e162;
    } else {
        let _e163 = (*eta_2);
        local_28 = (1f / max(_e163, 0.001f));
    }
    let _e166 = local_28;
    e_1 = _e166;
    let _e167 = (*mu_4);
    param_124 = _e167;
    let _e168 = (*alpha_10);
    param_125 = _e168;
    let _e169 = e_1;
    param_126 = _e169;
    let _e170 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_124), (&param_125), (&param_126));
    return _e170.x;
}

fn mxc_fon_albedo_u0028_f1_u003b_f1_u003b(sigma_1: ptr<function, f32>, mu_5: ptr<function, f32>) -> f32 {
    var a_4: f32;
    var c_7: f32;
    var s_10: f32;
    var param_127: f32;
    var theta: f32;
    var tail: f32;
    var local_29: f32;
    var g: f32;

    let _e162 = (*sigma_1);
    a_4 = (1f / (1f + (0.2877934f * _e162)));
    let _e166 = (*mu_5);
    c_7 = clamp(_e166, 0f, 1f);
    let _e168 = c_7;
    let _e169 = c_7;
    param_127 = (1f - (_e168 * _e169));
    let _e172 = mxc_safe_sqrt_u0028_f1_u003b((&param_127));
    s_10 = _e172;
    let _e173 = c_7;
    theta = acos(_e173);
    let _e175 = c_7;
    if (_e175 > 0.0001f) {
        let _e177 = s_10;
        let _e178 = s_10;
        let _e180 = s_10;
        let _e183 = c_7;
        local_29 = ((1f - ((_e177 * _e178) * _e180)) / _e183);
    } else {
        let _e185 = c_7;
        local_29 = (1.5f * _e185);
    }
    let _e187 = local_29;
    tail = _e187;
    let _e188 = s_10;
    let _e189 = theta;
    let _e190 = s_10;
    let _e191 = c_7;
    let _e195 = s_10;
    let _e197 = tail;
    let _e200 = s_10;
    g = (((_e188 * (_e189 - (_e190 * _e191))) + ((0.6666667f * _e195) * _e197)) - (0.6666667f * _e200));
    let _e203 = a_4;
    let _e204 = (*sigma_1);
    let _e205 = a_4;
    let _e207 = g;
    return (_e203 + (((_e204 * _e205) * _e207) * 0.31830987f));
}

fn mxc_table_u0028_f1_u003b_f1_u003b(mu_6: ptr<function, f32>, x_5: ptr<function, f32>) -> vec4<f32> {
    var param_128: f32;
    var param_129: f32;
    var param_130: f32;

    let _e157 = (*mu_6);
    param_128 = _e157;
    let _e158 = (*x_5);
    param_129 = _e158;
    param_130 = 0f;
    let _e159 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_128), (&param_129), (&param_130));
    return _e159;
}

fn mxc_split_sum_u0028_f1_u003b_f1_u003b(mu_7: ptr<function, f32>, alpha_11: ptr<function, f32>) -> vec2<f32> {
    var param_131: f32;
    var param_132: f32;

    let _e156 = (*alpha_11);
    let _e159 = (*mu_7);
    param_131 = _e159;
    param_132 = sqrt(max(_e156, 0f));
    let _e160 = mxc_table_u0028_f1_u003b_f1_u003b((&param_131), (&param_132));
    return _e160.xy;
}

fn mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_11: ptr<function, MxcLobe>, wo_10: ptr<function, vec3<f32>>, ms: ptr<function, vec3<f32>>) -> vec3<f32> {
    var mu_8: f32;
    var alpha_12: f32;
    var param_133: vec2<f32>;
    var e_2: vec3<f32>;
    var param_134: f32;
    var param_135: f32;
    var param_136: f32;
    var ab: vec2<f32>;
    var param_137: f32;
    var param_138: f32;
    var f0_: vec3<f32>;
    var param_139: MxcLobe;
    var param_140: f32;
    var param_141: bool;
    var f90_: vec3<f32>;
    var param_142: MxcLobe;
    var param_143: f32;
    var param_144: bool;
    var tint_1: vec3<f32>;
    var local_30: vec3<f32>;
    var param_145: vec2<f32>;
    var param_146: MxcLobe;
    var param_147: f32;
    var param_148: bool;
    var param_149: f32;
    var param_150: f32;
    var phi_2564_: bool;
    var phi_2571_: bool;
    var phi_2589_: bool;

    let _e182 = (*wo_10)[2u];
    mu_8 = clamp(_e182, 0f, 1f);
    let _e185 = (*l_11).kind;
    let _e186 = (_e185 == 1i);
    phi_2564_ = _e186;
    if !(_e186) {
        let _e189 = (*l_11).kind;
        phi_2564_ = (_e189 == 2i);
    }
    let _e192 = phi_2564_;
    phi_2571_ = _e192;
    if !(_e192) {
        let _e195 = (*l_11).kind;
        phi_2571_ = (_e195 == 3i);
    }
    let _e198 = phi_2571_;
    if _e198 {
        let _e201 = (*l_11).alpha[0u];
        let _e204 = (*l_11).alpha[1u];
        alpha_12 = sqrt((_e201 * _e204));
        let _e208 = (*l_11).kind;
        let _e209 = (_e208 == 1i);
        phi_2589_ = _e209;
        if _e209 {
            let _e211 = (*l_11).alpha;
            param_133 = _e211;
            let _e212 = mxc_is_delta_u0028_vf2_u003b((&param_133));
            phi_2589_ = !(_e212);
        }
        let _e215 = phi_2589_;
        if _e215 {
            let _e216 = mu_8;
            param_134 = _e216;
            let _e217 = alpha_12;
            param_135 = _e217;
            let _e219 = (*l_11).eta;
            param_136 = _e219;
            let _e220 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_134), (&param_135), (&param_136));
            e_2 = vec3(_e220);
            let _e222 = e_2;
            let _e224 = (*l_11).c0_;
            let _e226 = (*ms);
            return clamp(((_e222 * _e224) * _e226), vec3(0f), vec3(1f));
        }
        let _e231 = mu_8;
        param_137 = _e231;
        let _e232 = alpha_12;
        param_138 = _e232;
        let _e233 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_137), (&param_138));
        ab = _e233;
        let _e234 = (*l_11);
        param_139 = _e234;
        param_140 = 1f;
        param_141 = true;
        let _e235 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_139), (&param_140), (&param_141));
        f0_ = _e235;
        let _e236 = (*l_11);
        param_142 = _e236;
        param_143 = 0f;
        param_144 = true;
        let _e237 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_142), (&param_143), (&param_144));
        f90_ = _e237;
        let _e239 = (*l_11).kind;
        if (_e239 == 1i) {
            let _e242 = (*l_11).c0_;
            local_30 = _e242;
        } else {
            local_30 = vec3<f32>(1f, 1f, 1f);
        }
        let _e243 = local_30;
        tint_1 = _e243;
        let _e245 = (*l_11).alpha;
        param_145 = _e245;
        let _e246 = mxc_is_delta_u0028_vf2_u003b((&param_145));
        if _e246 {
            let _e247 = (*l_11);
            param_146 = _e247;
            let _e248 = mu_8;
            param_147 = _e248;
            param_148 = true;
            let _e249 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_146), (&param_147), (&param_148));
            let _e250 = tint_1;
            return (_e249 * _e250);
        }
        let _e252 = f0_;
        let _e254 = ab[0u];
        let _e256 = f90_;
        let _e258 = ab[1u];
        let _e261 = tint_1;
        let _e263 = (*ms);
        return clamp(((((_e252 * _e254) + (_e256 * _e258)) * _e261) * _e263), vec3(0f), vec3(1f));
    }
    let _e269 = (*l_11).kind;
    if (_e269 == 4i) {
        let _e272 = (*l_11).c0_;
        let _e274 = (*l_11).p0_;
        param_149 = _e274;
        let _e275 = mu_8;
        param_150 = _e275;
        let _e276 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_149), (&param_150));
        return (_e272 * _e276);
    }
    let _e279 = (*l_11).kind;
    if (_e279 == 8i) {
        let _e282 = (*l_11).c0_;
        return _e282;
    }
    let _e284 = (*l_11).c0_;
    return _e284;
}

fn mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_12: ptr<function, MxcLobe>, wo_11: ptr<function, vec3<f32>>) -> bool {
    var phi_2188_: bool;

    let _e155 = (*wo_11)[2u];
    let _e156 = (_e155 <= 0f);
    phi_2188_ = _e156;
    if !(_e156) {
        let _e159 = (*l_12).eta;
        phi_2188_ = (_e159 < 1f);
    }
    let _e162 = phi_2188_;
    if _e162 {
        return false;
    }
    return true;
}

fn mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_13: ptr<function, MxcLobe>) -> bool {
    let _e154 = (*l_13).eta;
    return (abs((_e154 - 1f)) < 0.0001f);
}

fn mxc_lobe_ms_shaped_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_14: ptr<function, MxcLobe>, wo_12: ptr<function, vec3<f32>>) -> bool {
    var param_151: vec2<f32>;
    var param_152: MxcLobe;
    var param_153: MxcLobe;
    var param_154: vec3<f32>;
    var phi_2441_: bool;
    var phi_2467_: bool;
    var phi_2474_: bool;
    var phi_2480_: bool;
    var phi_2486_: bool;

    let _e159 = (*wo_12)[2u];
    let _e160 = (_e159 <= 0f);
    phi_2441_ = _e160;
    if !(_e160) {
        let _e163 = (*l_14).alpha;
        param_151 = _e163;
        let _e164 = mxc_is_delta_u0028_vf2_u003b((&param_151));
        phi_2441_ = _e164;
    }
    let _e166 = phi_2441_;
    if _e166 {
        return false;
    }
    let _e168 = (*l_14).kind;
    if (_e168 == 2i) {
        return true;
    }
    let _e171 = (*l_14).kind;
    if (_e171 == 3i) {
        let _e174 = (*l_14).mode;
        return ((_e174 & 1i) != 0i);
    }
    let _e178 = (*l_14).kind;
    let _e179 = (_e178 == 1i);
    phi_2467_ = _e179;
    if _e179 {
        let _e181 = (*l_14).mode;
        phi_2467_ = ((_e181 & 1i) != 0i);
    }
    let _e185 = phi_2467_;
    phi_2474_ = _e185;
    if _e185 {
        let _e187 = (*l_14).mode;
        phi_2474_ = ((_e187 & 4i) == 0i);
    }
    let _e191 = phi_2474_;
    phi_2480_ = _e191;
    if _e191 {
        let _e192 = (*l_14);
        param_152 = _e192;
        let _e193 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_152));
        phi_2480_ = !(_e193);
    }
    let _e196 = phi_2480_;
    phi_2486_ = _e196;
    if _e196 {
        let _e197 = (*l_14);
        param_153 = _e197;
        let _e198 = (*wo_12);
        param_154 = _e198;
        let _e199 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_153), (&param_154));
        phi_2486_ = _e199;
    }
    let _e201 = phi_2486_;
    return _e201;
}

fn mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_15: ptr<function, MxcLobe>, woLocal: ptr<function, vec3<f32>>, ms_1: ptr<function, vec3<f32>>) -> f32 {
    var param_155: MxcLobe;
    var param_156: vec3<f32>;
    var param_157: vec3<f32>;
    var param_158: vec3<f32>;

    let _e160 = (*l_15).weight;
    if all((_e160 == vec3<f32>(0f, 0f, 0f))) {
        return 0f;
    }
    let _e164 = (*l_15).weight;
    let _e165 = (*l_15);
    param_155 = _e165;
    let _e166 = (*woLocal);
    param_156 = _e166;
    let _e167 = (*ms_1);
    param_157 = _e167;
    let _e168 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_155), (&param_156), (&param_157));
    param_158 = (_e164 * _e168);
    let _e170 = mxc_luminance_u0028_vf3_u003b((&param_158));
    return (max(_e170, 0f) + 0.0001f);
}

fn mxc_walk_texel_u0028_f1_u003b_f1_u003b(column: ptr<function, f32>, row: ptr<function, f32>) -> f32 {
    var t_4: vec2<f32>;

    let _e155 = (*column);
    let _e157 = (*row);
    t_4 = (vec2<f32>((_e155 + 0.5f), (_e157 + 0.5f)) / vec2<f32>(32f, 2070f));
    let _e161 = t_4;
    let _e162 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, _e161, 0f);
    return _e162.x;
}

fn mxc_walk_eta_index_u0028_f1_u003b(eta_3: ptr<function, f32>) -> f32 {
    var e_3: f32;

    let _e154 = (*eta_3);
    e_3 = max(_e154, 1f);
    let _e156 = e_3;
    let _e159 = e_3;
    return (clamp(((2f * (_e156 - 1f)) / (_e159 + 1f)), 0f, 1f) * 12f);
}

fn mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b(mu_9: ptr<function, f32>, alpha_13: ptr<function, f32>, eta_4: ptr<function, f32>) -> f32 {
    var fe: f32;
    var param_159: f32;
    var e0_: f32;
    var column_1: f32;
    var row_1: f32;
    var a_5: f32;
    var param_160: f32;
    var param_161: f32;
    var b_3: f32;
    var param_162: f32;
    var param_163: f32;

    let _e166 = (*eta_4);
    param_159 = _e166;
    let _e167 = mxc_walk_eta_index_u0028_f1_u003b((&param_159));
    fe = _e167;
    let _e168 = fe;
    e0_ = min(floor(_e168), 11f);
    let _e171 = (*mu_9);
    column_1 = (sqrt(clamp(_e171, 0f, 1f)) * 31f);
    let _e175 = (*alpha_13);
    row_1 = (1654f + (sqrt(clamp(_e175, 0f, 1f)) * 31f));
    let _e180 = row_1;
    let _e181 = e0_;
    let _e184 = column_1;
    param_160 = _e184;
    param_161 = (_e180 + (_e181 * 32f));
    let _e185 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_160), (&param_161));
    a_5 = _e185;
    let _e186 = row_1;
    let _e187 = e0_;
    let _e191 = column_1;
    param_162 = _e191;
    param_163 = (_e186 + ((_e187 + 1f) * 32f));
    let _e192 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_162), (&param_163));
    b_3 = _e192;
    let _e193 = a_5;
    let _e194 = b_3;
    let _e195 = fe;
    let _e196 = e0_;
    return mix(_e193, _e194, (_e195 - _e196));
}

fn mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_16: ptr<function, MxcLobe>, wo_13: ptr<function, vec3<f32>>, ms_2: ptr<function, vec3<f32>>) -> f32 {
    var param_164: vec2<f32>;
    var param_165: MxcLobe;
    var param_166: MxcLobe;
    var param_167: vec3<f32>;
    var alpha_14: f32;
    var rss: f32;
    var param_168: f32;
    var param_169: f32;
    var param_170: f32;
    var tss: f32;
    var param_171: f32;
    var param_172: f32;
    var param_173: f32;
    var param_174: f32;
    var param_175: f32;
    var param_176: f32;
    var phi_2221_: bool;
    var phi_2227_: bool;
    var phi_2235_: bool;
    var phi_2243_: bool;

    let _e172 = (*l_16).kind;
    let _e173 = (_e172 != 1i);
    phi_2221_ = _e173;
    if !(_e173) {
        let _e176 = (*l_16).alpha;
        param_164 = _e176;
        let _e177 = mxc_is_delta_u0028_vf2_u003b((&param_164));
        phi_2221_ = _e177;
    }
    let _e179 = phi_2221_;
    phi_2227_ = _e179;
    if !(_e179) {
        let _e181 = (*l_16);
        param_165 = _e181;
        let _e182 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_165));
        phi_2227_ = _e182;
    }
    let _e184 = phi_2227_;
    phi_2235_ = _e184;
    if !(_e184) {
        let _e187 = (*l_16).mode;
        phi_2235_ = ((_e187 & 4i) != 0i);
    }
    let _e191 = phi_2235_;
    phi_2243_ = _e191;
    if !(_e191) {
        let _e193 = (*l_16);
        param_166 = _e193;
        let _e194 = (*wo_13);
        param_167 = _e194;
        let _e195 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_166), (&param_167));
        phi_2243_ = !(_e195);
    }
    let _e198 = phi_2243_;
    if _e198 {
        let _e200 = (*ms_2)[0u];
        return _e200;
    }
    let _e203 = (*l_16).alpha[0u];
    let _e206 = (*l_16).alpha[1u];
    alpha_14 = sqrt((_e203 * _e206));
    let _e210 = (*wo_13)[2u];
    param_168 = _e210;
    let _e211 = alpha_14;
    param_169 = _e211;
    let _e213 = (*l_16).eta;
    param_170 = _e213;
    let _e214 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_168), (&param_169), (&param_170));
    rss = _e214;
    let _e216 = (*wo_13)[2u];
    param_171 = _e216;
    let _e217 = alpha_14;
    param_172 = _e217;
    let _e219 = (*l_16).eta;
    param_173 = _e219;
    let _e220 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_171), (&param_172), (&param_173));
    let _e221 = rss;
    tss = (_e220 - _e221);
    let _e224 = (*wo_13)[2u];
    param_174 = _e224;
    let _e225 = alpha_14;
    param_175 = _e225;
    let _e227 = (*l_16).eta;
    param_176 = _e227;
    let _e228 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_174), (&param_175), (&param_176));
    let _e230 = tss;
    return clamp(((1f - _e228) / max(_e230, 0.05f)), 1f, 20f);
}

fn mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_17: ptr<function, MxcLobe>, wo_14: ptr<function, vec3<f32>>) -> vec3<f32> {
    var microfacet: bool;
    var param_177: vec2<f32>;
    var alpha_15: f32;
    var param_178: MxcLobe;
    var param_179: MxcLobe;
    var param_180: vec3<f32>;
    var rss_1: f32;
    var param_181: f32;
    var param_182: f32;
    var param_183: f32;
    var param_184: f32;
    var param_185: f32;
    var param_186: f32;
    var e_4: f32;
    var param_187: MxcLobe;
    var param_188: bool;
    var param_189: f32;
    var param_190: f32;
    var param_191: f32;
    var k_3: vec3<f32>;
    var ab_1: vec2<f32>;
    var param_192: f32;
    var param_193: f32;
    var e_5: f32;
    var param_194: MxcLobe;
    var param_195: f32;
    var param_196: bool;
    var phi_2319_: bool;
    var phi_2326_: bool;
    var phi_2335_: bool;
    var phi_2351_: bool;
    var phi_2363_: bool;

    let _e182 = (*l_17).kind;
    let _e183 = (_e182 == 1i);
    phi_2319_ = _e183;
    if !(_e183) {
        let _e186 = (*l_17).kind;
        phi_2319_ = (_e186 == 2i);
    }
    let _e189 = phi_2319_;
    phi_2326_ = _e189;
    if !(_e189) {
        let _e192 = (*l_17).kind;
        phi_2326_ = (_e192 == 3i);
    }
    let _e195 = phi_2326_;
    microfacet = _e195;
    let _e196 = microfacet;
    let _e197 = !(_e196);
    phi_2335_ = _e197;
    if !(_e197) {
        let _e200 = (*l_17).alpha;
        param_177 = _e200;
        let _e201 = mxc_is_delta_u0028_vf2_u003b((&param_177));
        phi_2335_ = _e201;
    }
    let _e203 = phi_2335_;
    if _e203 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e206 = (*l_17).alpha[0u];
    let _e209 = (*l_17).alpha[1u];
    alpha_15 = sqrt((_e206 * _e209));
    let _e213 = (*l_17).kind;
    let _e214 = (_e213 == 1i);
    phi_2351_ = _e214;
    if _e214 {
        let _e215 = (*l_17);
        param_178 = _e215;
        let _e216 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_178));
        phi_2351_ = _e216;
    }
    let _e218 = phi_2351_;
    if _e218 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e220 = (*l_17).kind;
    let _e221 = (_e220 == 1i);
    phi_2363_ = _e221;
    if _e221 {
        let _e223 = (*l_17).mode;
        phi_2363_ = ((_e223 & 4i) == 0i);
    }
    let _e227 = phi_2363_;
    if _e227 {
        let _e228 = (*l_17);
        param_179 = _e228;
        let _e229 = (*wo_14);
        param_180 = _e229;
        let _e230 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_179), (&param_180));
        if _e230 {
            let _e232 = (*wo_14)[2u];
            param_181 = _e232;
            let _e233 = alpha_15;
            param_182 = _e233;
            let _e235 = (*l_17).eta;
            param_183 = _e235;
            let _e236 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_181), (&param_182), (&param_183));
            rss_1 = _e236;
            let _e238 = (*wo_14)[2u];
            param_184 = _e238;
            let _e239 = alpha_15;
            param_185 = _e239;
            let _e241 = (*l_17).eta;
            param_186 = _e241;
            let _e242 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_184), (&param_185), (&param_186));
            let _e243 = rss_1;
            return vec3(clamp((_e242 / max(_e243, 0.0001f)), 1f, 20f));
        }
        let _e249 = (*wo_14)[2u];
        let _e252 = (*wo_14)[2u];
        let _e254 = (*l_17);
        param_187 = _e254;
        param_188 = (_e252 >= 0f);
        let _e255 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_187), (&param_188));
        param_189 = abs(_e249);
        let _e256 = alpha_15;
        param_190 = _e256;
        param_191 = _e255;
        let _e257 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_189), (&param_190), (&param_191));
        e_4 = _e257;
        let _e258 = e_4;
        k_3 = vec3((1f / max(_e258, 0.05f)));
        let _e262 = k_3;
        return _e262;
    }
    let _e264 = (*wo_14)[2u];
    param_192 = max(_e264, 0f);
    let _e266 = alpha_15;
    param_193 = _e266;
    let _e267 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_192), (&param_193));
    ab_1 = _e267;
    let _e269 = ab_1[0u];
    let _e271 = ab_1[1u];
    e_5 = (_e269 + _e271);
    let _e273 = (*l_17);
    param_194 = _e273;
    param_195 = 1f;
    param_196 = true;
    let _e274 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_194), (&param_195), (&param_196));
    let _e275 = e_5;
    let _e278 = e_5;
    return (vec3(1f) + ((_e274 * (1f - _e275)) / vec3(max(_e278, 0.05f))));
}

fn mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b(c_8: ptr<function, MxcClosure>, wo_15: ptr<function, vec3<f32>>) {
    var k_4: i32;
    var l_18: MxcLobe;
    var o_4: vec3<f32>;
    var param_197: vec3<f32>;
    var param_198: vec3<f32>;
    var param_199: mat3x3<f32>;
    var param_200: vec3<f32>;
    var ms_3: vec3<f32>;
    var param_201: MxcLobe;
    var param_202: vec3<f32>;
    var param_203: MxcLobe;
    var param_204: vec3<f32>;
    var param_205: vec3<f32>;
    var param_206: MxcLobe;
    var param_207: vec3<f32>;
    var param_208: vec3<f32>;
    var param_209: MxcLobe;
    var param_210: vec3<f32>;
    var alpha_16: f32;
    var reflected_1: vec3<f32>;
    var param_211: MxcLobe;
    var param_212: vec3<f32>;
    var param_213: vec3<f32>;
    var addedR: vec3<f32>;
    var param_214: MxcLobe;
    var param_215: vec3<f32>;
    var param_216: vec3<f32>;
    var transmitted_1: vec3<f32>;
    var addedT: vec3<f32>;
    var param_217: MxcLobe;
    var rss_2: f32;
    var param_218: f32;
    var param_219: f32;
    var param_220: f32;
    var param_221: f32;
    var param_222: f32;
    var param_223: f32;
    var mr: MxcLobe;
    var param_224: MxcLobe;
    var param_225: bool;
    var broadR: vec3<f32>;
    var param_226: MxcLobe;
    var param_227: vec3<f32>;
    var param_228: vec3<f32>;
    var broadT: f32;
    var param_229: MxcLobe;
    var mt: MxcLobe;
    var param_230: MxcLobe;
    var param_231: bool;
    var at: f32;
    var param_232: f32;
    var param_233: f32;
    var param_234: f32;
    var param_235: f32;
    var param_236: f32;
    var param_237: f32;
    var total_1: f32;
    var param_238: vec3<f32>;
    var added: f32;
    var param_239: vec3<f32>;
    var local_31: f32;
    var param_240: vec3<f32>;
    var phi_3357_: bool;
    var phi_3397_: bool;

    (*c_8).choiceTotal = 0f;
    k_4 = 0i;
    loop {
        let _e217 = k_4;
        let _e219 = (*c_8).count;
        if (_e217 < _e219) {
            let _e221 = k_4;
            let _e224 = (*c_8).lobes[_e221];
            l_18 = _e224;
            let _e225 = k_4;
            (*c_8).ms[_e225] = vec3<f32>(1f, 1f, 1f);
            let _e228 = k_4;
            (*c_8).msT[_e228] = 1f;
            let _e231 = k_4;
            (*c_8).msLobe[_e231] = vec3<f32>(0f, 0f, 0f);
            let _e234 = k_4;
            (*c_8).msLobeT[_e234] = vec3<f32>(0f, 0f, 0f);
            let _e237 = k_4;
            (*c_8).msPick[_e237] = 0f;
            let _e240 = k_4;
            (*c_8).msSplit[_e240] = 1f;
            let _e243 = k_4;
            (*c_8).choice[_e243] = 0f;
            let _e247 = l_18.weight;
            if all((_e247 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e251 = l_18.N;
            param_197 = _e251;
            let _e253 = l_18.T;
            param_198 = _e253;
            let _e254 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_197), (&param_198));
            param_199 = _e254;
            let _e255 = (*wo_15);
            param_200 = _e255;
            let _e256 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_199), (&param_200));
            o_4 = _e256;
            let _e257 = l_18;
            param_201 = _e257;
            let _e258 = o_4;
            param_202 = _e258;
            let _e259 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_201), (&param_202));
            ms_3 = _e259;
            let _e260 = k_4;
            let _e261 = l_18;
            param_203 = _e261;
            let _e262 = o_4;
            param_204 = _e262;
            let _e263 = ms_3;
            param_205 = _e263;
            let _e264 = mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_203), (&param_204), (&param_205));
            (*c_8).msT[_e260] = _e264;
            let _e267 = k_4;
            let _e268 = l_18;
            param_206 = _e268;
            let _e269 = o_4;
            param_207 = _e269;
            let _e270 = ms_3;
            param_208 = _e270;
            let _e271 = mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_206), (&param_207), (&param_208));
            (*c_8).choice[_e267] = _e271;
            let _e274 = k_4;
            let _e277 = (*c_8).choice[_e274];
            let _e279 = (*c_8).choiceTotal;
            (*c_8).choiceTotal = (_e279 + _e277);
            let _e282 = l_18;
            param_209 = _e282;
            let _e283 = o_4;
            param_210 = _e283;
            let _e284 = mxc_lobe_ms_shaped_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_209), (&param_210));
            if _e284 {
                let _e287 = l_18.alpha[0u];
                let _e290 = l_18.alpha[1u];
                alpha_16 = sqrt((_e287 * _e290));
                let _e293 = l_18;
                param_211 = _e293;
                let _e294 = o_4;
                param_212 = _e294;
                param_213 = vec3<f32>(1f, 1f, 1f);
                let _e295 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_211), (&param_212), (&param_213));
                reflected_1 = _e295;
                let _e296 = l_18;
                param_214 = _e296;
                let _e297 = o_4;
                param_215 = _e297;
                let _e298 = ms_3;
                param_216 = _e298;
                let _e299 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_214), (&param_215), (&param_216));
                let _e300 = reflected_1;
                addedR = max((_e299 - _e300), vec3<f32>(0f, 0f, 0f));
                transmitted_1 = vec3<f32>(0f, 0f, 0f);
                addedT = vec3<f32>(0f, 0f, 0f);
                let _e304 = l_18.kind;
                let _e305 = (_e304 == 1i);
                phi_3357_ = _e305;
                if _e305 {
                    let _e306 = l_18;
                    param_217 = _e306;
                    let _e307 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_217));
                    phi_3357_ = _e307;
                }
                let _e309 = phi_3357_;
                if _e309 {
                    let _e311 = o_4[2u];
                    param_218 = _e311;
                    let _e312 = alpha_16;
                    param_219 = _e312;
                    let _e314 = l_18.eta;
                    param_220 = _e314;
                    let _e315 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_218), (&param_219), (&param_220));
                    rss_2 = _e315;
                    let _e317 = o_4[2u];
                    param_221 = _e317;
                    let _e318 = alpha_16;
                    param_222 = _e318;
                    let _e320 = l_18.eta;
                    param_223 = _e320;
                    let _e321 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_221), (&param_222), (&param_223));
                    let _e322 = rss_2;
                    let _e326 = l_18.c1_;
                    transmitted_1 = (_e326 * max((_e321 - _e322), 0f));
                    let _e328 = k_4;
                    let _e331 = (*c_8).msT[_e328];
                    let _e334 = transmitted_1;
                    addedT = (_e334 * max((_e331 - 1f), 0f));
                }
                let _e336 = l_18;
                param_224 = _e336;
                param_225 = false;
                let _e337 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_224), (&param_225));
                mr = _e337;
                let _e338 = mr;
                param_226 = _e338;
                let _e339 = o_4;
                param_227 = _e339;
                param_228 = vec3<f32>(1f, 1f, 1f);
                let _e340 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_226), (&param_227), (&param_228));
                broadR = _e340;
                broadT = 1f;
                let _e342 = l_18.kind;
                let _e343 = (_e342 == 1i);
                phi_3397_ = _e343;
                if _e343 {
                    let _e344 = l_18;
                    param_229 = _e344;
                    let _e345 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_229));
                    phi_3397_ = _e345;
                }
                let _e347 = phi_3397_;
                if _e347 {
                    let _e348 = l_18;
                    param_230 = _e348;
                    param_231 = true;
                    let _e349 = mxc_ms_lobe_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_230), (&param_231));
                    mt = _e349;
                    let _e352 = mt.alpha[0u];
                    let _e355 = mt.alpha[1u];
                    at = sqrt((_e352 * _e355));
                    let _e359 = o_4[2u];
                    param_232 = _e359;
                    let _e360 = at;
                    param_233 = _e360;
                    let _e362 = l_18.eta;
                    param_234 = _e362;
                    let _e363 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_232), (&param_233), (&param_234));
                    let _e365 = o_4[2u];
                    param_235 = _e365;
                    let _e366 = at;
                    param_236 = _e366;
                    let _e368 = l_18.eta;
                    param_237 = _e368;
                    let _e369 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_235), (&param_236), (&param_237));
                    broadT = (_e363 - _e369);
                }
                let _e371 = k_4;
                let _e372 = addedR;
                let _e373 = broadR;
                (*c_8).msLobe[_e371] = (_e372 / max(_e373, vec3<f32>(0.0001f, 0.0001f, 0.0001f)));
                let _e378 = k_4;
                let _e379 = addedT;
                let _e380 = broadT;
                (*c_8).msLobeT[_e378] = (_e379 / vec3(max(_e380, 0.0001f)));
                let _e386 = reflected_1;
                let _e387 = addedR;
                let _e389 = transmitted_1;
                let _e391 = addedT;
                param_238 = (((_e386 + _e387) + _e389) + _e391);
                let _e393 = mxc_luminance_u0028_vf3_u003b((&param_238));
                total_1 = max(_e393, 0.000001f);
                let _e395 = addedR;
                let _e396 = addedT;
                param_239 = (_e395 + _e396);
                let _e398 = mxc_luminance_u0028_vf3_u003b((&param_239));
                added = _e398;
                let _e399 = k_4;
                let _e400 = added;
                let _e401 = total_1;
                (*c_8).msPick[_e399] = (0.999f * min((_e400 / _e401), 1f));
                let _e407 = k_4;
                let _e408 = added;
                if (_e408 > 0f) {
                    let _e410 = addedR;
                    param_240 = _e410;
                    let _e411 = mxc_luminance_u0028_vf3_u003b((&param_240));
                    let _e412 = added;
                    local_31 = (_e411 / _e412);
                } else {
                    local_31 = 1f;
                }
                let _e414 = local_31;
                (*c_8).msSplit[_e407] = _e414;
                let _e417 = k_4;
                (*c_8).msT[_e417] = 1f;
            } else {
                let _e420 = k_4;
                let _e421 = ms_3;
                (*c_8).ms[_e420] = _e421;
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e424 = k_4;
            k_4 = (_e424 + 1i);
        }
    }
    return;
}

fn mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_19: ptr<function, MxcLobe>, wo_16: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_241: MxcLobe;
    var param_242: vec3<f32>;
    var param_243: MxcLobe;
    var param_244: vec3<f32>;
    var param_245: vec3<f32>;

    let _e159 = (*l_19);
    param_241 = _e159;
    let _e160 = (*wo_16);
    param_242 = _e160;
    let _e161 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_241), (&param_242));
    let _e162 = (*l_19);
    param_243 = _e162;
    let _e163 = (*wo_16);
    param_244 = _e163;
    param_245 = _e161;
    let _e164 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_243), (&param_244), (&param_245));
    return _e164;
}

fn mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_20: ptr<function, MxcLobe>, wo_17: ptr<function, vec3<f32>>) -> vec3<f32> {
    var white: MxcLobe;
    var param_246: MxcLobe;
    var param_247: vec3<f32>;
    var param_248: MxcLobe;
    var param_249: vec3<f32>;
    var phi_2703_: bool;

    let _e160 = (*l_20).kind;
    let _e161 = (_e160 == 9i);
    phi_2703_ = _e161;
    if !(_e161) {
        let _e164 = (*l_20).kind;
        phi_2703_ = (_e164 == 10i);
    }
    let _e167 = phi_2703_;
    if _e167 {
        let _e168 = (*l_20);
        white = _e168;
        white.c0_ = vec3<f32>(1f, 1f, 1f);
        let _e170 = white;
        param_246 = _e170;
        let _e171 = (*wo_17);
        param_247 = _e171;
        let _e172 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_246), (&param_247));
        return _e172;
    }
    let _e173 = (*l_20);
    param_248 = _e173;
    let _e174 = (*wo_17);
    param_249 = _e174;
    let _e175 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_248), (&param_249));
    return _e175;
}

fn mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b(v_7: ptr<function, vec3<f32>>, fallback: ptr<function, vec3<f32>>) -> vec3<f32> {
    var l2_1: f32;
    var local_32: vec3<f32>;

    let _e156 = (*v_7);
    let _e157 = (*v_7);
    l2_1 = dot(_e156, _e157);
    let _e159 = l2_1;
    if (_e159 > 0.00000000000000000001f) {
        let _e161 = (*v_7);
        let _e162 = l2_1;
        local_32 = (_e161 * inverseSqrt(_e162));
    } else {
        let _e165 = (*fallback);
        local_32 = _e165;
    }
    let _e166 = local_32;
    return _e166;
}

fn mxc_normalmap_u0028_vf3_u003b_vf2_u003b_vf3_u003b_vf3_u003b_vf3_u003b(sampleValue: ptr<function, vec3<f32>>, scale_1: ptr<function, vec2<f32>>, N_1: ptr<function, vec3<f32>>, T_1: ptr<function, vec3<f32>>, B: ptr<function, vec3<f32>>) -> vec3<f32> {
    var v_8: vec3<f32>;
    var param_250: vec3<f32>;
    var param_251: vec3<f32>;

    let _e160 = (*sampleValue);
    v_8 = ((_e160 * 2f) - vec3(1f));
    let _e164 = (*scale_1);
    let _e165 = v_8;
    let _e167 = (_e165.xy * _e164);
    v_8[0u] = _e167.x;
    v_8[1u] = _e167.y;
    let _e172 = (*T_1);
    let _e174 = v_8[0u];
    let _e176 = (*B);
    let _e178 = v_8[1u];
    let _e181 = (*N_1);
    let _e183 = v_8[2u];
    param_250 = (((_e172 * _e174) + (_e176 * _e178)) + (_e181 * _e183));
    let _e186 = (*N_1);
    param_251 = _e186;
    let _e187 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_250), (&param_251));
    return _e187;
}

fn mxc_hsv_to_rgb_u0028_vf3_u003b(hsv: ptr<function, vec3<f32>>) -> vec3<f32> {
    var k_5: vec3<f32>;

    let _e155 = (*hsv)[0u];
    k_5 = clamp((abs(((fract((vec3(_e155) + vec3<f32>(0f, 0.6666667f, 0.33333334f))) * 6f) - vec3(3f))) - vec3(1f)), vec3(0f), vec3(1f));
    let _e169 = (*hsv)[2u];
    let _e170 = k_5;
    let _e172 = (*hsv)[1u];
    return (mix(vec3<f32>(1f, 1f, 1f), _e170, vec3(_e172)) * _e169);
}

fn mxc_address_u0028_f1_u003b_i1_u003b(x_6: ptr<function, f32>, mode: ptr<function, i32>) -> bool {
    let _e154 = (*mode);
    if (_e154 == 0i) {
        let _e156 = (*x_6);
        let _e158 = (*x_6);
        return ((_e156 >= 0f) && (_e158 <= 1f));
    }
    let _e161 = (*mode);
    if (_e161 == 1i) {
        let _e163 = (*x_6);
        (*x_6) = clamp(_e163, 0f, 1f);
    } else {
        let _e165 = (*mode);
        if (_e165 == 2i) {
            let _e167 = (*x_6);
            (*x_6) = fract(_e167);
        } else {
            let _e169 = (*x_6);
            (*x_6) = (1f - abs(((_e169 - (floor((_e169 / 2f)) * 2f)) - 1f)));
        }
    }
    return true;
}

fn mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(image_texture: texture_2d<f32>, image_sampler: sampler, uv_1: ptr<function, vec2<f32>>, fallback_1: ptr<function, vec4<f32>>, uaddress: ptr<function, i32>, vaddress: ptr<function, i32>, filtertype: ptr<function, i32>, missing: ptr<function, bool>) -> vec4<f32> {
    var dx: vec2<f32>;
    var dy: vec2<f32>;
    var st: vec2<f32>;
    var param_252: f32;
    var param_253: i32;
    var param_254: f32;
    var param_255: i32;
    var size_2: vec2<f32>;
    var phi_1678_: bool;

    let _e168 = (*uv_1);
    let _e169 = dpdx(_e168);
    let _e170 = mxc_texture_footprint;
    let _e171 = mxc_texture_footprint;
    dx = (_e169 * vec2<f32>(_e170, -(_e171)));
    let _e175 = (*uv_1);
    let _e176 = dpdy(_e175);
    let _e177 = mxc_texture_footprint;
    let _e178 = mxc_texture_footprint;
    dy = (_e176 * vec2<f32>(_e177, -(_e178)));
    let _e182 = (*uv_1);
    st = _e182;
    let _e183 = (*missing);
    if _e183 {
        let _e184 = (*fallback_1);
        return _e184;
    }
    let _e186 = st[0u];
    param_252 = _e186;
    let _e187 = (*uaddress);
    param_253 = _e187;
    let _e188 = mxc_address_u0028_f1_u003b_i1_u003b((&param_252), (&param_253));
    let _e189 = param_252;
    st[0u] = _e189;
    let _e191 = !(_e188);
    phi_1678_ = _e191;
    if !(_e191) {
        let _e194 = st[1u];
        param_254 = _e194;
        let _e195 = (*vaddress);
        param_255 = _e195;
        let _e196 = mxc_address_u0028_f1_u003b_i1_u003b((&param_254), (&param_255));
        let _e197 = param_254;
        st[1u] = _e197;
        phi_1678_ = !(_e196);
    }
    let _e201 = phi_1678_;
    if _e201 {
        let _e202 = (*fallback_1);
        return _e202;
    }
    let _e204 = st[1u];
    st[1u] = (1f - _e204);
    let _e207 = (*filtertype);
    if (_e207 == 1i) {
        let _e209 = textureDimensions(image_texture, 0i);
        size_2 = vec2<f32>(vec2<i32>(_e209));
        let _e212 = st;
        let _e213 = size_2;
        let _e216 = size_2;
        let _e222 = size_2;
        let _e224 = textureSampleLevel(image_texture, image_sampler, ((min(floor((_e212 * _e213)), (_e216 - vec2(1f))) + vec2(0.5f)) / _e222), 0f);
        return _e224;
    }
    let _e225 = st;
    let _e226 = dx;
    let _e227 = dy;
    let _e228 = textureSampleGrad(image_texture, image_sampler, _e225, _e226, _e227);
    return _e228;
}

fn mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b(g_1: ptr<function, MxcGeometry>, wo_18: ptr<function, vec3<f32>>, c_9: ptr<function, MxcClosure>) {
    var v3_: vec2<f32>;
    var v4_: vec2<f32>;
    var v8_: f32;
    var param_256: vec2<f32>;
    var param_257: vec4<f32>;
    var param_258: i32;
    var param_259: i32;
    var param_260: i32;
    var param_261: bool;
    var v10_: f32;
    var v11_: f32;
    var v13_: f32;
    var param_262: vec2<f32>;
    var param_263: vec4<f32>;
    var param_264: i32;
    var param_265: i32;
    var param_266: i32;
    var param_267: bool;
    var v14_: f32;
    var v20_: f32;
    var param_268: vec2<f32>;
    var param_269: vec4<f32>;
    var param_270: i32;
    var param_271: i32;
    var param_272: i32;
    var param_273: bool;
    var v21_: f32;
    var v25_: f32;
    var param_274: vec2<f32>;
    var param_275: vec4<f32>;
    var param_276: i32;
    var param_277: i32;
    var param_278: i32;
    var param_279: bool;
    var v26_: f32;
    var v28_: f32;
    var param_280: vec2<f32>;
    var param_281: vec4<f32>;
    var param_282: i32;
    var param_283: i32;
    var param_284: i32;
    var param_285: bool;
    var v29_: f32;
    var v31_: f32;
    var v32_: f32;
    var v34_: f32;
    var v35_: f32;
    var v36_: vec3<f32>;
    var v38_: vec3<f32>;
    var v39_: vec3<f32>;
    var param_286: vec3<f32>;
    var v40_: vec3<f32>;
    var v41_: vec3<f32>;
    var v43_: vec3<f32>;
    var v44_: vec3<f32>;
    var v45_: vec3<f32>;
    var v46_: vec3<f32>;
    var v48_: vec3<f32>;
    var param_287: vec2<f32>;
    var param_288: vec4<f32>;
    var param_289: i32;
    var param_290: i32;
    var param_291: i32;
    var param_292: bool;
    var v49_: vec3<f32>;
    var v50_: vec3<f32>;
    var v51_: vec3<f32>;
    var v52_: vec3<f32>;
    var param_293: vec3<f32>;
    var param_294: vec2<f32>;
    var param_295: vec3<f32>;
    var param_296: vec3<f32>;
    var param_297: vec3<f32>;
    var v55_: f32;
    var v56_: f32;
    var v57_: vec2<f32>;
    var lobe0_: MxcLobe;
    var param_298: vec3<f32>;
    var param_299: vec3<f32>;
    var e1_: vec3<f32>;
    var param_300: vec3<f32>;
    var param_301: vec3<f32>;
    var param_302: mat3x3<f32>;
    var param_303: vec3<f32>;
    var param_304: MxcLobe;
    var param_305: vec3<f32>;
    var w2_: vec3<f32>;
    var lobe3_: MxcLobe;
    var param_306: vec3<f32>;
    var param_307: vec3<f32>;
    var param_308: MxcClosure;
    var param_309: vec3<f32>;

    let _e248 = (*g_1).uv;
    v3_ = _e248;
    let _e249 = v3_;
    v4_ = (_e249 * vec2<f32>(3f, 3f));
    let _e252 = mxc_params.missing_textures;
    let _e255 = v4_;
    param_256 = _e255;
    param_257 = vec4<f32>(0f, 0f, 0f, 0f);
    param_258 = 2i;
    param_259 = 2i;
    param_260 = 0i;
    param_261 = ((_e252 & 1u) != 0u);
    let _e256 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_0_texture, mxc_texture_0_sampler, (&param_256), (&param_257), (&param_258), (&param_259), (&param_260), (&param_261));
    v8_ = _e256.x;
    let _e258 = v8_;
    v10_ = max(_e258, 0.00001f);
    let _e260 = v10_;
    v11_ = (0.853f / _e260);
    let _e263 = mxc_params.missing_textures;
    let _e266 = v4_;
    param_262 = _e266;
    param_263 = vec4<f32>(0f, 0f, 0f, 0f);
    param_264 = 2i;
    param_265 = 2i;
    param_266 = 0i;
    param_267 = ((_e263 & 2u) != 0u);
    let _e267 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_1_texture, mxc_texture_1_sampler, (&param_262), (&param_263), (&param_264), (&param_265), (&param_266), (&param_267));
    v13_ = _e267.x;
    let _e269 = v11_;
    let _e270 = v13_;
    v14_ = (_e269 * _e270);
    let _e273 = mxc_params.missing_textures;
    let _e276 = v4_;
    param_268 = _e276;
    param_269 = vec4<f32>(0f, 0f, 0f, 0f);
    param_270 = 2i;
    param_271 = 2i;
    param_272 = 0i;
    param_273 = ((_e273 & 4u) != 0u);
    let _e277 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_2_texture, mxc_texture_2_sampler, (&param_268), (&param_269), (&param_270), (&param_271), (&param_272), (&param_273));
    v20_ = _e277.x;
    let _e279 = v20_;
    v21_ = (0.248f * _e279);
    let _e282 = mxc_params.missing_textures;
    let _e285 = v4_;
    param_274 = _e285;
    param_275 = vec4<f32>(0f, 0f, 0f, 0f);
    param_276 = 2i;
    param_277 = 2i;
    param_278 = 0i;
    param_279 = ((_e282 & 8u) != 0u);
    let _e286 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_3_texture, mxc_texture_3_sampler, (&param_274), (&param_275), (&param_276), (&param_277), (&param_278), (&param_279));
    v25_ = _e286.x;
    let _e288 = v25_;
    v26_ = (0.083f * _e288);
    let _e291 = mxc_params.missing_textures;
    let _e294 = v4_;
    param_280 = _e294;
    param_281 = vec4<f32>(0f, 0f, 0f, 0f);
    param_282 = 2i;
    param_283 = 2i;
    param_284 = 0i;
    param_285 = ((_e291 & 16u) != 0u);
    let _e295 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_4_texture, mxc_texture_4_sampler, (&param_280), (&param_281), (&param_282), (&param_283), (&param_284), (&param_285));
    v28_ = _e295.x;
    let _e297 = v26_;
    let _e298 = v28_;
    v29_ = (_e297 + _e298);
    let _e300 = v29_;
    v31_ = (_e300 - 0.35f);
    let _e302 = v31_;
    v32_ = (_e302 * 0.083f);
    let _e304 = v25_;
    v34_ = (0.787f * _e304);
    let _e306 = v29_;
    let _e307 = v34_;
    v35_ = (_e306 * _e307);
    let _e309 = v32_;
    let _e310 = v35_;
    v36_ = vec3<f32>(_e309, 0f, _e310);
    let _e312 = v36_;
    v38_ = (_e312 + vec3<f32>(0.048065394f, 1f, 0.661876f));
    let _e314 = v38_;
    param_286 = _e314;
    let _e315 = mxc_hsv_to_rgb_u0028_vf3_u003b((&param_286));
    v39_ = _e315;
    let _e316 = v39_;
    let _e317 = v21_;
    v40_ = mix(_e316, vec3<f32>(0.56372f, 0.56372f, 0.56372f), vec3(_e317));
    let _e320 = v40_;
    let _e321 = v28_;
    v41_ = (_e320 * _e321);
    let _e323 = v28_;
    v43_ = (vec3<f32>(0.263273f, 0.263273f, 0.263273f) * _e323);
    let _e325 = v43_;
    let _e326 = v41_;
    let _e327 = v8_;
    v44_ = mix(_e325, _e326, vec3(_e327));
    let _e330 = v44_;
    v45_ = clamp(_e330, vec3<f32>(0f, 0f, 0f), vec3<f32>(1f, 1f, 1f));
    let _e332 = v45_;
    v46_ = clamp(_e332, vec3<f32>(0f, 0f, 0f), vec3<f32>(1f, 1f, 1f));
    let _e335 = mxc_params.missing_textures;
    let _e338 = v4_;
    param_287 = _e338;
    param_288 = vec4<f32>(0f, 0f, 0f, 1f);
    param_289 = 2i;
    param_290 = 2i;
    param_291 = 0i;
    param_292 = ((_e335 & 32u) != 0u);
    let _e339 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_5_texture, mxc_texture_5_sampler, (&param_287), (&param_288), (&param_289), (&param_290), (&param_291), (&param_292));
    v48_ = _e339.xyz;
    let _e342 = (*g_1).N;
    v49_ = _e342;
    let _e344 = (*g_1).T;
    v50_ = _e344;
    let _e346 = (*g_1).B;
    v51_ = _e346;
    let _e347 = v48_;
    param_293 = _e347;
    param_294 = vec2<f32>(1f, 1f);
    let _e348 = v49_;
    param_295 = _e348;
    let _e349 = v50_;
    param_296 = _e349;
    let _e350 = v51_;
    param_297 = _e350;
    let _e351 = mxc_normalmap_u0028_vf3_u003b_vf2_u003b_vf3_u003b_vf3_u003b_vf3_u003b((&param_293), (&param_294), (&param_295), (&param_296), (&param_297));
    v52_ = _e351;
    let _e352 = v14_;
    let _e353 = v14_;
    v55_ = (_e352 * _e353);
    let _e355 = v55_;
    v56_ = clamp(_e355, 0.0000001f, 1f);
    let _e357 = v56_;
    let _e358 = v56_;
    v57_ = vec2<f32>(_e357, _e358);
    (*c_9).emission = vec3<f32>(0f, 0f, 0f);
    (*c_9).transparency = vec3<f32>(0f, 0f, 0f);
    lobe0_.kind = 1i;
    lobe0_.mode = 1i;
    let _e364 = v52_;
    param_298 = _e364;
    let _e366 = (*g_1).N;
    param_299 = _e366;
    let _e367 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_298), (&param_299));
    lobe0_.N = _e367;
    let _e369 = v50_;
    lobe0_.T = _e369;
    let _e371 = v57_;
    lobe0_.alpha = _e371;
    lobe0_.eta = 1.5f;
    lobe0_.c0_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.p0_ = 0f;
    lobe0_.p1_ = 1f;
    lobe0_.film = vec3<f32>(0f, 0f, 0f);
    lobe0_.tau = vec3<f32>(0f, 0f, 0f);
    lobe0_.tauEta = 1f;
    let _e383 = lobe0_.N;
    param_300 = _e383;
    let _e385 = lobe0_.T;
    param_301 = _e385;
    let _e386 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_300), (&param_301));
    param_302 = _e386;
    let _e387 = (*wo_18);
    param_303 = _e387;
    let _e388 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_302), (&param_303));
    let _e389 = lobe0_;
    param_304 = _e389;
    param_305 = _e388;
    let _e390 = mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_304), (&param_305));
    e1_ = _e390;
    let _e391 = e1_;
    w2_ = (vec3<f32>(1f, 1f, 1f) - _e391);
    lobe3_.kind = 4i;
    lobe3_.mode = 1i;
    let _e395 = v52_;
    param_306 = _e395;
    let _e397 = (*g_1).N;
    param_307 = _e397;
    let _e398 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_306), (&param_307));
    lobe3_.N = _e398;
    let _e401 = (*g_1).T;
    lobe3_.T = _e401;
    lobe3_.alpha = vec2<f32>(0f, 0f);
    lobe3_.eta = 1.5f;
    let _e405 = v46_;
    lobe3_.c0_ = _e405;
    lobe3_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.p0_ = 0f;
    lobe3_.p1_ = 1f;
    lobe3_.film = vec3<f32>(0f, 0f, 0f);
    lobe3_.tau = vec3<f32>(0f, 0f, 0f);
    lobe3_.tauEta = 1f;
    lobe0_.weight = vec3<f32>(1f, 1f, 1f);
    let _e415 = lobe0_;
    (*c_9).lobes[0i] = _e415;
    let _e418 = w2_;
    lobe3_.weight = _e418;
    let _e420 = lobe3_;
    (*c_9).lobes[1i] = _e420;
    (*c_9).count = 2i;
    let _e424 = (*c_9);
    param_308 = _e424;
    let _e425 = (*wo_18);
    param_309 = _e425;
    mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b((&param_308), (&param_309));
    let _e426 = param_308;
    (*c_9) = _e426;
    return;
}

fn mxc_closure_seed_u0028_u1_u003b(seed_1: ptr<function, u32>) {
    return;
}

fn main_1() {
    var g_2: MxcGeometry;
    var N_2: vec3<f32>;
    var param_310: vec3<f32>;
    var param_311: vec3<f32>;
    var wo_19: vec3<f32>;
    var param_312: vec3<f32>;
    var param_313: vec3<f32>;
    var facing: f32;
    var handedness: f32;
    var frame_4: mat3x3<f32>;
    var param_314: vec3<f32>;
    var param_315: vec3<f32>;
    var param_316: vec3<f32>;
    var param_317: vec3<f32>;
    var objectFrame: mat3x3<f32>;
    var param_318: vec3<f32>;
    var param_319: vec3<f32>;
    var param_320: u32;
    var param_321: u32;
    var param_322: u32;
    var param_323: u32;
    var c_10: MxcClosure;
    var param_324: MxcGeometry;
    var param_325: vec3<f32>;
    var param_326: MxcClosure;
    var radiance: vec3<f32>;
    var lights: i32;
    var kinds: i32;
    var image: bool;
    var n_1: i32;
    var local_33: i32;
    var seed_2: u32;
    var param_327: u32;
    var param_328: u32;
    var param_329: u32;
    var pixel: u32;
    var param_330: u32;
    var param_331: u32;
    var shift: vec4<f32>;
    var param_332: u32;
    var param_333: u32;
    var param_334: u32;
    var param_335: u32;
    var sum: vec3<f32>;
    var b_4: i32;
    var batchLights: i32;
    var batchSamples: i32;
    var local_34: i32;
    var index: u32;
    var choice: vec4<f32>;
    var param_336: u32;
    var param_337: u32;
    var param_338: u32;
    var param_339: u32;
    var param_340: u32;
    var param_341: u32;
    var param_342: u32;
    var param_343: u32;
    var smp: MxcSample;
    var param_344: MxcClosure;
    var param_345: vec3<f32>;
    var param_346: vec3<f32>;
    var above_4: bool;
    var seen: vec3<f32>;
    var local_35: vec3<f32>;
    var local_36: vec3<f32>;
    var param_347: vec3<f32>;
    var param_348: vec3<f32>;
    var param_349: vec3<f32>;
    var w_1: f32;
    var local_37: f32;
    var param_350: vec3<f32>;
    var param_351: f32;
    var param_352: vec3<f32>;
    var param_353: f32;
    var param_354: f32;
    var m_8: vec3<f32>;
    var lightPdf: f32;
    var imageWi: vec3<f32>;
    var imageSeen: vec3<f32>;
    var v_9: vec4<f32>;
    var param_355: u32;
    var param_356: u32;
    var param_357: u32;
    var param_358: vec4<f32>;
    var param_359: f32;
    var param_360: vec3<f32>;
    var param_361: f32;
    var param_362: vec3<f32>;
    var j_2: i32;
    var wi_6: vec3<f32>;
    var incoming: vec3<f32>;
    var use_: bool;
    var strategy: i32;
    var local_38: i32;
    var light: vec4<f32>;
    var directional: bool;
    var param_363: vec3<f32>;
    var param_364: vec3<f32>;
    var d_8: vec3<f32>;
    var d2_: f32;
    var spot: vec4<f32>;
    var f_5: vec3<f32>;
    var pdf_2: f32;
    var param_365: MxcClosure;
    var param_366: vec3<f32>;
    var param_367: vec3<f32>;
    var param_368: bool;
    var param_369: f32;
    var w_2: f32;
    var local_39: f32;
    var param_370: vec3<f32>;
    var param_371: f32;
    var param_372: vec3<f32>;
    var param_373: f32;
    var param_374: f32;
    var w_3: f32;
    var param_375: vec3<f32>;
    var param_376: f32;
    var param_377: f32;
    var coverage: f32;
    var param_378: vec3<f32>;
    var phi_668_: bool;
    var phi_679_: bool;
    var phi_741_: bool;
    var phi_798_: bool;
    var phi_799_: bool;
    var phi_832_: bool;
    var phi_874_: bool;

    mxc_texture_footprint = 1f;
    let _e274 = vPosition_1;
    g_2.P = _e274;
    let _e276 = vObjectPosition_1;
    g_2.Pobj = _e276;
    let _e278 = vNormal_1;
    param_310 = _e278;
    param_311 = vec3<f32>(0f, 0f, 1f);
    let _e279 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_310), (&param_311));
    N_2 = _e279;
    let _e280 = gl_FrontFacing_1;
    if !(_e280) {
        let _e282 = N_2;
        N_2 = -(_e282);
    }
    let _e285 = mxc_view.eye;
    let _e287 = vPosition_1;
    param_312 = (_e285.xyz - _e287);
    let _e289 = N_2;
    param_313 = _e289;
    let _e290 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_312), (&param_313));
    wo_19 = _e290;
    let _e291 = wo_19;
    let _e292 = N_2;
    facing = dot(_e291, _e292);
    let _e294 = facing;
    if (_e294 < 0.01f) {
        let _e296 = N_2;
        let _e297 = facing;
        let _e299 = wo_19;
        N_2 = normalize((_e296 + (_e299 * (0.01f - _e297))));
    }
    let _e304 = vTangent_1[3u];
    handedness = select(1f, -1f, (_e304 < 0f));
    let _e307 = N_2;
    param_314 = _e307;
    let _e308 = vTangent_1;
    param_315 = _e308.xyz;
    let _e310 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_314), (&param_315));
    frame_4 = _e310;
    let _e311 = N_2;
    g_2.N = _e311;
    let _e314 = frame_4[0];
    g_2.T = _e314;
    let _e317 = frame_4[1];
    let _e318 = handedness;
    g_2.B = (_e317 * _e318);
    let _e321 = vObjectNormal_1;
    param_316 = _e321;
    param_317 = vec3<f32>(0f, 0f, 1f);
    let _e322 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_316), (&param_317));
    g_2.Nobj = _e322;
    let _e325 = g_2.Nobj;
    param_318 = _e325;
    let _e326 = vObjectTangent_1;
    param_319 = _e326;
    let _e327 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_318), (&param_319));
    objectFrame = _e327;
    let _e329 = objectFrame[0];
    g_2.Tobj = _e329;
    let _e332 = objectFrame[1];
    let _e333 = handedness;
    g_2.Bobj = (_e332 * _e333);
    let _e336 = vUv_1;
    g_2.uv = _e336;
    g_2.color = vec4<f32>(1f, 1f, 1f, 1f);
    let _e340 = mxc_view.objectToWorld;
    g_2.objectToWorld = _e340;
    let _e343 = mxc_params.frame;
    g_2.frame = _e343;
    let _e346 = mxc_params.time;
    g_2.time = _e346;
    let _e350 = mxc_view.jitter[2u];
    mxc_texture_footprint = _e350;
    let _e351 = mxc_texture_footprint;
    if !((_e351 > 0f)) {
        mxc_texture_footprint = 1f;
    }
    let _e355 = gl_FragCoord_1[0u];
    let _e358 = gl_FragCoord_1[1u];
    let _e362 = mxc_view.counts[2u];
    param_320 = (bitcast<u32>(_e362) + 7u);
    let _e365 = mxc_pcg_u0028_u1_u003b((&param_320));
    param_321 = (u32(_e358) + _e365);
    let _e367 = mxc_pcg_u0028_u1_u003b((&param_321));
    param_322 = (u32(_e355) ^ _e367);
    let _e369 = mxc_pcg_u0028_u1_u003b((&param_322));
    param_323 = _e369;
    mxc_closure_seed_u0028_u1_u003b((&param_323));
    let _e370 = g_2;
    param_324 = _e370;
    let _e371 = wo_19;
    param_325 = _e371;
    mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b((&param_324), (&param_325), (&param_326));
    let _e372 = param_326;
    c_10 = _e372;
    let _e374 = c_10.emission;
    let _e377 = mxc_view.environment[1u];
    radiance = (_e374 * _e377);
    let _e379 = mxc_light_count_u0028_();
    lights = _e379;
    let _e380 = mxc_light_kinds_u0028_();
    kinds = _e380;
    let _e381 = mxc_environment_code_u0028_();
    image = (_e381 == 3i);
    let _e383 = mxc_environment_code_u0028_();
    if (_e383 != 0i) {
        let _e387 = mxc_view.counts[3u];
        local_33 = max(_e387, 1i);
    } else {
        local_33 = 0i;
    }
    let _e389 = local_33;
    n_1 = _e389;
    let _e391 = gl_FragCoord_1[0u];
    let _e394 = gl_FragCoord_1[1u];
    let _e398 = mxc_view.counts[2u];
    param_327 = bitcast<u32>(_e398);
    let _e400 = mxc_pcg_u0028_u1_u003b((&param_327));
    param_328 = (u32(_e394) + _e400);
    let _e402 = mxc_pcg_u0028_u1_u003b((&param_328));
    param_329 = (u32(_e391) + _e402);
    let _e404 = mxc_pcg_u0028_u1_u003b((&param_329));
    seed_2 = _e404;
    let _e406 = gl_FragCoord_1[0u];
    let _e409 = gl_FragCoord_1[1u];
    param_330 = (u32(_e409) + 2654435769u);
    let _e412 = mxc_pcg_u0028_u1_u003b((&param_330));
    param_331 = (u32(_e406) ^ _e412);
    let _e414 = mxc_pcg_u0028_u1_u003b((&param_331));
    pixel = _e414;
    let _e415 = pixel;
    param_332 = _e415;
    let _e416 = mxc_uniform_u0028_u1_u003b((&param_332));
    let _e417 = param_332;
    pixel = _e417;
    let _e418 = pixel;
    param_333 = _e418;
    let _e419 = mxc_uniform_u0028_u1_u003b((&param_333));
    let _e420 = param_333;
    pixel = _e420;
    let _e421 = pixel;
    param_334 = _e421;
    let _e422 = mxc_uniform_u0028_u1_u003b((&param_334));
    let _e423 = param_334;
    pixel = _e423;
    let _e424 = pixel;
    param_335 = _e424;
    let _e425 = mxc_uniform_u0028_u1_u003b((&param_335));
    let _e426 = param_335;
    pixel = _e426;
    shift = vec4<f32>(_e416, _e419, _e422, _e425);
    sum = vec3<f32>(0f, 0f, 0f);
    b_4 = 0i;
    loop {
        let _e428 = b_4;
        let _e429 = n_1;
        let _e430 = lights;
        if (_e428 < max(_e429, select(0i, 1i, (_e430 > 0i)))) {
            let _e435 = b_4;
            let _e437 = lights;
            batchLights = select(0i, _e437, (_e435 == 0i));
            let _e439 = b_4;
            let _e440 = n_1;
            if (_e439 < _e440) {
                let _e442 = image;
                local_34 = (1i + select(0i, 1i, _e442));
            } else {
                local_34 = 0i;
            }
            let _e445 = local_34;
            batchSamples = _e445;
            let _e448 = mxc_view.counts[2u];
            let _e450 = n_1;
            let _e454 = b_4;
            index = ((bitcast<u32>(_e448) * bitcast<u32>(max(_e450, 1i))) + bitcast<u32>(_e454));
            let _e457 = index;
            param_336 = _e457;
            param_337 = 2u;
            let _e458 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_336), (&param_337));
            let _e459 = index;
            param_338 = _e459;
            param_339 = 3u;
            let _e460 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_338), (&param_339));
            let _e461 = index;
            param_340 = _e461;
            param_341 = 5u;
            let _e462 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_340), (&param_341));
            let _e463 = index;
            param_342 = _e463;
            param_343 = 7u;
            let _e464 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_342), (&param_343));
            let _e466 = shift;
            choice = fract((vec4<f32>(_e458, _e460, _e462, _e464) + _e466));
            smp.valid = false;
            smp.evaluate = false;
            smp.delta = false;
            smp.pdf = 0f;
            smp.weight = vec3<f32>(0f, 0f, 0f);
            let _e474 = N_2;
            smp.wi = _e474;
            let _e476 = n_1;
            if (_e476 > 0i) {
                let _e479 = choice[2u];
                let _e481 = choice[3u];
                let _e483 = choice[0u];
                let _e485 = c_10;
                param_344 = _e485;
                let _e486 = wo_19;
                param_345 = _e486;
                param_346 = vec3<f32>(_e479, _e481, _e483);
                let _e487 = mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b((&param_344), (&param_345), (&param_346));
                smp = _e487;
            }
            let _e489 = smp.wi;
            let _e490 = N_2;
            above_4 = (dot(_e489, _e490) > 0f);
            let _e494 = smp.valid;
            if _e494 {
                let _e495 = above_4;
                if _e495 {
                    let _e497 = smp.wi;
                    local_36 = _e497;
                } else {
                    let _e498 = wo_19;
                    param_347 = -(_e498);
                    let _e501 = smp.wi;
                    param_348 = _e501;
                    let _e502 = mxc_exit_direction_u0028_vf3_u003b_vf3_u003b((&param_347), (&param_348));
                    local_36 = _e502;
                }
                let _e503 = local_36;
                param_349 = _e503;
                let _e504 = mxc_environment_u0028_vf3_u003b((&param_349));
                local_35 = _e504;
            } else {
                local_35 = vec3<f32>(0f, 0f, 0f);
            }
            let _e505 = local_35;
            seen = _e505;
            let _e506 = b_4;
            let _e507 = n_1;
            let _e510 = smp.valid;
            let _e511 = ((_e506 < _e507) && _e510);
            phi_668_ = _e511;
            if _e511 {
                let _e513 = smp.evaluate;
                phi_668_ = !(_e513);
            }
            let _e516 = phi_668_;
            if _e516 {
                let _e517 = image;
                let _e518 = above_4;
                let _e519 = (_e517 && _e518);
                phi_679_ = _e519;
                if _e519 {
                    let _e521 = smp.delta;
                    phi_679_ = !(_e521);
                }
                let _e524 = phi_679_;
                if _e524 {
                    let _e526 = smp.wi;
                    param_350 = _e526;
                    let _e529 = mxc_view.environment[2u];
                    param_351 = _e529;
                    let _e530 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_350), (&param_351));
                    param_352 = _e530;
                    let _e531 = mxc_env_pdf_u0028_vf3_u003b((&param_352));
                    let _e533 = smp.pdf;
                    param_353 = _e533;
                    param_354 = _e531;
                    let _e534 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_353), (&param_354));
                    local_37 = _e534;
                } else {
                    local_37 = 1f;
                }
                let _e535 = local_37;
                w_1 = _e535;
                let _e536 = w_1;
                let _e538 = smp.weight;
                let _e540 = seen;
                let _e542 = sum;
                sum = (_e542 + ((_e538 * _e536) * _e540));
            }
            m_8 = vec3<f32>(0f, 0f, 0f);
            lightPdf = 0f;
            let _e544 = N_2;
            imageWi = _e544;
            imageSeen = vec3<f32>(0f, 0f, 0f);
            let _e545 = image;
            let _e546 = b_4;
            let _e547 = n_1;
            if (_e545 && (_e546 < _e547)) {
                let _e551 = choice[1u];
                let _e552 = seed_2;
                param_355 = _e552;
                let _e553 = mxc_uniform_u0028_u1_u003b((&param_355));
                let _e554 = param_355;
                seed_2 = _e554;
                let _e555 = seed_2;
                param_356 = _e555;
                let _e556 = mxc_uniform_u0028_u1_u003b((&param_356));
                let _e557 = param_356;
                seed_2 = _e557;
                let _e558 = seed_2;
                param_357 = _e558;
                let _e559 = mxc_uniform_u0028_u1_u003b((&param_357));
                let _e560 = param_357;
                seed_2 = _e560;
                v_9 = vec4<f32>(_e551, _e553, _e556, _e559);
                let _e562 = v_9;
                param_358 = _e562;
                let _e563 = mxc_env_sample_u0028_vf4_u003b_f1_u003b((&param_358), (&param_359));
                let _e564 = param_359;
                lightPdf = _e564;
                m_8 = _e563;
                let _e565 = m_8;
                param_360 = _e565;
                let _e568 = mxc_view.environment[2u];
                param_361 = _e568;
                let _e569 = mxc_env_to_world_u0028_vf3_u003b_f1_u003b((&param_360), (&param_361));
                imageWi = _e569;
                let _e570 = lightPdf;
                let _e571 = (_e570 > 0f);
                phi_741_ = _e571;
                if _e571 {
                    let _e572 = imageWi;
                    let _e573 = N_2;
                    phi_741_ = (dot(_e572, _e573) > 0f);
                }
                let _e577 = phi_741_;
                if _e577 {
                    let _e578 = imageWi;
                    param_362 = _e578;
                    let _e579 = mxc_environment_u0028_vf3_u003b((&param_362));
                    imageSeen = _e579;
                }
            }
            j_2 = 0i;
            loop {
                let _e580 = j_2;
                let _e581 = batchLights;
                let _e582 = batchSamples;
                if (_e580 < (_e581 + _e582)) {
                    let _e585 = N_2;
                    wi_6 = _e585;
                    incoming = vec3<f32>(0f, 0f, 0f);
                    use_ = true;
                    let _e586 = n_1;
                    let _e588 = j_2;
                    let _e589 = batchLights;
                    if ((_e586 == 0i) || (_e588 < _e589)) {
                        local_38 = 0i;
                    } else {
                        let _e592 = j_2;
                        let _e593 = batchLights;
                        local_38 = select(2i, 1i, (_e592 == ((_e593 + 1i) - 1i)));
                    }
                    let _e598 = local_38;
                    strategy = _e598;
                    let _e599 = strategy;
                    if (_e599 == 0i) {
                        let _e601 = j_2;
                        let _e604 = mxc_view.lightVector[_e601];
                        light = _e604;
                        let _e605 = j_2;
                        let _e608 = mxc_view.lightRadiance[_e605];
                        incoming = _e608.xyz;
                        let _e610 = kinds;
                        let _e611 = (_e610 == 1i);
                        phi_799_ = _e611;
                        if !(_e611) {
                            let _e613 = kinds;
                            let _e615 = ((_e613 & 1i) != 0i);
                            phi_798_ = _e615;
                            if _e615 {
                                let _e617 = light[3u];
                                phi_798_ = (_e617 == 0f);
                            }
                            let _e620 = phi_798_;
                            phi_799_ = _e620;
                        }
                        let _e622 = phi_799_;
                        directional = _e622;
                        let _e623 = directional;
                        if _e623 {
                            let _e624 = light;
                            param_363 = _e624.xyz;
                            let _e626 = N_2;
                            param_364 = _e626;
                            let _e627 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_363), (&param_364));
                            wi_6 = _e627;
                        } else {
                            let _e628 = light;
                            let _e630 = vPosition_1;
                            d_8 = (_e628.xyz - _e630);
                            let _e632 = d_8;
                            let _e633 = d_8;
                            d2_ = max(dot(_e632, _e633), 0.00000001f);
                            let _e636 = d_8;
                            let _e637 = d2_;
                            wi_6 = (_e636 * inverseSqrt(_e637));
                            let _e640 = d2_;
                            let _e641 = incoming;
                            incoming = (_e641 / vec3(_e640));
                            let _e644 = kinds;
                            let _e646 = ((_e644 & 4i) != 0i);
                            phi_832_ = _e646;
                            if _e646 {
                                let _e648 = light[3u];
                                phi_832_ = (_e648 == 2f);
                            }
                            let _e651 = phi_832_;
                            if _e651 {
                                let _e652 = j_2;
                                let _e655 = mxc_view.lightSpot[_e652];
                                spot = _e655;
                                let _e657 = spot[3u];
                                let _e658 = j_2;
                                let _e662 = mxc_view.lightRadiance[_e658][3u];
                                let _e663 = wi_6;
                                let _e665 = spot;
                                let _e669 = incoming;
                                incoming = (_e669 * smoothstep(_e657, _e662, dot(-(_e663), _e665.xyz)));
                            }
                        }
                    } else {
                        let _e671 = strategy;
                        if (_e671 == 1i) {
                            let _e674 = smp.wi;
                            wi_6 = _e674;
                            let _e675 = seen;
                            incoming = _e675;
                            let _e677 = smp.valid;
                            let _e679 = smp.evaluate;
                            use_ = (_e677 && _e679);
                        } else {
                            let _e681 = imageWi;
                            wi_6 = _e681;
                            let _e682 = imageSeen;
                            incoming = _e682;
                            let _e683 = lightPdf;
                            let _e684 = (_e683 > 0f);
                            phi_874_ = _e684;
                            if _e684 {
                                let _e685 = imageWi;
                                let _e686 = N_2;
                                phi_874_ = (dot(_e685, _e686) > 0f);
                            }
                            let _e690 = phi_874_;
                            use_ = _e690;
                        }
                    }
                    let _e691 = strategy;
                    let _e693 = c_10;
                    param_365 = _e693;
                    let _e694 = wo_19;
                    param_366 = _e694;
                    let _e695 = wi_6;
                    param_367 = _e695;
                    param_368 = (_e691 != 0i);
                    let _e696 = mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b((&param_365), (&param_366), (&param_367), (&param_368), (&param_369));
                    let _e697 = param_369;
                    pdf_2 = _e697;
                    f_5 = _e696;
                    let _e698 = strategy;
                    if (_e698 == 0i) {
                        let _e700 = f_5;
                        let _e701 = incoming;
                        let _e703 = radiance;
                        radiance = (_e703 + (_e700 * _e701));
                    } else {
                        let _e705 = strategy;
                        if (_e705 == 1i) {
                            let _e707 = use_;
                            let _e708 = pdf_2;
                            if (_e707 && (_e708 > 0f)) {
                                let _e711 = image;
                                let _e712 = above_4;
                                if (_e711 && _e712) {
                                    let _e714 = wi_6;
                                    param_370 = _e714;
                                    let _e717 = mxc_view.environment[2u];
                                    param_371 = _e717;
                                    let _e718 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_370), (&param_371));
                                    param_372 = _e718;
                                    let _e719 = mxc_env_pdf_u0028_vf3_u003b((&param_372));
                                    let _e720 = pdf_2;
                                    param_373 = _e720;
                                    param_374 = _e719;
                                    let _e721 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_373), (&param_374));
                                    local_39 = _e721;
                                } else {
                                    local_39 = 1f;
                                }
                                let _e722 = local_39;
                                w_2 = _e722;
                                let _e723 = w_2;
                                let _e724 = f_5;
                                let _e726 = pdf_2;
                                let _e729 = incoming;
                                let _e731 = sum;
                                sum = (_e731 + (((_e724 * _e723) / vec3(_e726)) * _e729));
                            }
                        } else {
                            let _e733 = use_;
                            if _e733 {
                                let _e734 = m_8;
                                param_375 = _e734;
                                let _e735 = mxc_env_pdf_u0028_vf3_u003b((&param_375));
                                param_376 = _e735;
                                let _e736 = pdf_2;
                                param_377 = _e736;
                                let _e737 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_376), (&param_377));
                                w_3 = _e737;
                                let _e738 = w_3;
                                let _e739 = f_5;
                                let _e741 = incoming;
                                let _e743 = lightPdf;
                                let _e746 = sum;
                                sum = (_e746 + (((_e739 * _e738) * _e741) / vec3(_e743)));
                            }
                        }
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e748 = j_2;
                    j_2 = (_e748 + 1i);
                }
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e750 = b_4;
            b_4 = (_e750 + 1i);
        }
    }
    let _e752 = sum;
    let _e753 = n_1;
    let _e758 = radiance;
    radiance = (_e758 + (_e752 / vec3(f32(max(_e753, 1i)))));
    let _e761 = c_10.transparency;
    param_378 = _e761;
    let _e762 = mxc_luminance_u0028_vf3_u003b((&param_378));
    coverage = (1f - clamp(_e762, 0f, 1f));
    let _e765 = radiance;
    let _e766 = coverage;
    outColor = vec4<f32>(_e765.x, _e765.y, _e765.z, _e766);
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
