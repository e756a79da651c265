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
    let _e149 = (*c);
    return dot(_e149, vec3<f32>(0.2126f, 0.7152f, 0.0722f));
}

fn mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l: ptr<function, MxcLobe>) -> bool {
    return false;
}

fn mxc_mean_u0028_vf3_u003b(c_1: ptr<function, vec3<f32>>) -> f32 {
    let _e150 = (*c_1)[0u];
    let _e152 = (*c_1)[1u];
    let _e155 = (*c_1)[2u];
    return (((_e150 + _e152) + _e155) * 0.33333334f);
}

fn mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b(cosi: ptr<function, f32>, eta: ptr<function, f32>) -> f32 {
    var sin2t: f32;
    var cost: f32;
    var rs: f32;
    var rp: f32;

    let _e154 = (*eta);
    if (abs((_e154 - 1f)) < 0.000001f) {
        return 0f;
    }
    let _e158 = (*cosi);
    let _e159 = (*cosi);
    let _e162 = (*eta);
    let _e163 = (*eta);
    sin2t = ((1f - (_e158 * _e159)) / (_e162 * _e163));
    let _e166 = sin2t;
    if (_e166 >= 1f) {
        return 1f;
    }
    let _e168 = sin2t;
    cost = sqrt((1f - _e168));
    let _e171 = (*cosi);
    let _e172 = (*eta);
    let _e173 = cost;
    let _e176 = (*cosi);
    let _e177 = (*eta);
    let _e178 = cost;
    rs = ((_e171 - (_e172 * _e173)) / (_e176 + (_e177 * _e178)));
    let _e182 = (*eta);
    let _e183 = (*cosi);
    let _e185 = cost;
    let _e187 = (*eta);
    let _e188 = (*cosi);
    let _e190 = cost;
    rp = (((_e182 * _e183) - _e185) / ((_e187 * _e188) + _e190));
    let _e193 = rs;
    let _e194 = rs;
    let _e196 = rp;
    let _e197 = rp;
    return (0.5f * ((_e193 * _e194) + (_e196 * _e197)));
}

fn mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b(l_1: ptr<function, MxcLobe>, above: ptr<function, bool>) -> f32 {
    var local: f32;

    let _e151 = (*above);
    if _e151 {
        let _e153 = (*l_1).eta;
        local = _e153;
    } else {
        let _e155 = (*l_1).eta;
        local = (1f / _e155);
    }
    let _e157 = local;
    return _e157;
}

fn mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b(l_2: ptr<function, MxcLobe>, cosh_: ptr<function, f32>, above_1: ptr<function, bool>) -> vec3<f32> {
    var f: vec3<f32>;
    var param: MxcLobe;
    var param_1: bool;
    var param_2: f32;
    var param_3: f32;

    f = vec3<f32>(1f, 1f, 1f);
    let _e157 = (*l_2).kind;
    if (_e157 == 1i) {
        let _e159 = (*l_2);
        param = _e159;
        let _e160 = (*above_1);
        param_1 = _e160;
        let _e161 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param), (&param_1));
        let _e162 = (*cosh_);
        param_2 = _e162;
        param_3 = _e161;
        let _e163 = mxc_fresnel_dielectric_u0028_f1_u003b_f1_u003b((&param_2), (&param_3));
        f = vec3(_e163);
    }
    let _e165 = f;
    return _e165;
}

fn mxc_rough_alpha_u0028_vf2_u003b(alpha: ptr<function, vec2<f32>>) -> vec2<f32> {
    let _e149 = (*alpha);
    return max(_e149, vec2<f32>(0.0001f, 0.0001f));
}

fn mxc_ggx_d_u0028_vf3_u003b_vf2_u003b(m: ptr<function, vec3<f32>>, alpha_1: ptr<function, vec2<f32>>) -> f32 {
    var param_4: vec2<f32>;
    var s: vec3<f32>;
    var d: f32;

    let _e154 = (*m)[2u];
    if (_e154 <= 0f) {
        return 0f;
    }
    let _e156 = (*alpha_1);
    param_4 = _e156;
    let _e157 = mxc_rough_alpha_u0028_vf2_u003b((&param_4));
    (*alpha_1) = _e157;
    let _e159 = (*m)[0u];
    let _e161 = (*alpha_1)[0u];
    let _e164 = (*m)[1u];
    let _e166 = (*alpha_1)[1u];
    let _e169 = (*m)[2u];
    s = vec3<f32>((_e159 / _e161), (_e164 / _e166), _e169);
    let _e171 = s;
    let _e172 = s;
    d = dot(_e171, _e172);
    let _e175 = (*alpha_1)[0u];
    let _e178 = (*alpha_1)[1u];
    let _e180 = d;
    let _e182 = d;
    return (1f / ((((3.1415927f * _e175) * _e178) * _e180) * _e182));
}

fn mxc_sqr_u0028_f1_u003b(x: ptr<function, f32>) -> f32 {
    let _e149 = (*x);
    let _e150 = (*x);
    return (_e149 * _e150);
}

fn mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b(v: ptr<function, vec3<f32>>, alpha_2: ptr<function, vec2<f32>>) -> f32 {
    var param_5: vec2<f32>;
    var z2_: f32;
    var a2_: f32;
    var param_6: f32;
    var param_7: f32;

    let _e155 = (*alpha_2);
    param_5 = _e155;
    let _e156 = mxc_rough_alpha_u0028_vf2_u003b((&param_5));
    (*alpha_2) = _e156;
    let _e158 = (*v)[2u];
    let _e160 = (*v)[2u];
    z2_ = (_e158 * _e160);
    let _e162 = z2_;
    if (_e162 <= 0f) {
        return 10000000000f;
    }
    let _e165 = (*alpha_2)[0u];
    let _e167 = (*v)[0u];
    param_6 = (_e165 * _e167);
    let _e169 = mxc_sqr_u0028_f1_u003b((&param_6));
    let _e171 = (*alpha_2)[1u];
    let _e173 = (*v)[1u];
    param_7 = (_e171 * _e173);
    let _e175 = mxc_sqr_u0028_f1_u003b((&param_7));
    let _e177 = z2_;
    a2_ = ((_e169 + _e175) / _e177);
    let _e179 = a2_;
    return (0.5f * (-1f + sqrt((1f + _e179))));
}

fn mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b(v_1: ptr<function, vec3<f32>>, alpha_3: ptr<function, vec2<f32>>) -> f32 {
    var param_8: vec3<f32>;
    var param_9: vec2<f32>;

    let _e152 = (*v_1);
    param_8 = _e152;
    let _e153 = (*alpha_3);
    param_9 = _e153;
    let _e154 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_8), (&param_9));
    return (1f / (1f + _e154));
}

fn mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo: ptr<function, vec3<f32>>, m_1: ptr<function, vec3<f32>>, alpha_4: ptr<function, vec2<f32>>) -> f32 {
    var param_10: vec3<f32>;
    var param_11: vec2<f32>;
    var param_12: vec3<f32>;
    var param_13: vec2<f32>;

    let _e156 = (*wo)[2u];
    if (_e156 <= 0f) {
        return 0f;
    }
    let _e158 = (*wo);
    param_10 = _e158;
    let _e159 = (*alpha_4);
    param_11 = _e159;
    let _e160 = mxc_ggx_g1_u0028_vf3_u003b_vf2_u003b((&param_10), (&param_11));
    let _e161 = (*wo);
    let _e162 = (*m_1);
    let _e166 = (*m_1);
    param_12 = _e166;
    let _e167 = (*alpha_4);
    param_13 = _e167;
    let _e168 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_12), (&param_13));
    let _e171 = (*wo)[2u];
    return (((_e160 * max(dot(_e161, _e162), 0f)) * _e168) / _e171);
}

fn mxc_is_delta_u0028_vf2_u003b(alpha_5: ptr<function, vec2<f32>>) -> bool {
    let _e150 = (*alpha_5)[0u];
    let _e152 = (*alpha_5)[1u];
    return (max(_e150, _e152) < 0.0001f);
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
    var phi_2749_: bool;
    var phi_2830_: bool;

    let _e170 = (*l_3).kind;
    switch _e170 {
        case 2, 3, 1: {
            let _e184 = (*l_3).alpha;
            param_14 = _e184;
            let _e185 = mxc_is_delta_u0028_vf2_u003b((&param_14));
            if _e185 {
                return 0f;
            }
            let _e187 = (*wo_1)[2u];
            above_2 = (_e187 > 0f);
            let _e189 = above_2;
            if _e189 {
                let _e190 = (*wo_1);
                local_1 = _e190;
            } else {
                let _e191 = (*wo_1);
                local_1 = -(_e191);
            }
            let _e193 = local_1;
            o = _e193;
            let _e194 = above_2;
            if _e194 {
                let _e195 = (*wi);
                local_2 = _e195;
            } else {
                let _e196 = (*wi);
                local_2 = -(_e196);
            }
            let _e198 = local_2;
            i = _e198;
            let _e200 = i[2u];
            if (_e200 > 0f) {
                let _e202 = o;
                let _e203 = i;
                h = normalize((_e202 + _e203));
                let _e206 = o;
                param_15 = _e206;
                let _e207 = h;
                param_16 = _e207;
                let _e209 = (*l_3).alpha;
                param_17 = _e209;
                let _e210 = mxc_ggx_pdf_vndf_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_15), (&param_16), (&param_17));
                let _e211 = o;
                let _e212 = h;
                p = (_e210 / (4f * max(dot(_e211, _e212), 0.000001f)));
                let _e218 = (*l_3).kind;
                if (_e218 == 2i) {
                    let _e220 = p;
                    return _e220;
                }
                let _e222 = (*l_3).mode;
                if ((_e222 & 1i) == 0i) {
                    return 0f;
                }
                let _e225 = o;
                let _e226 = h;
                let _e229 = (*l_3);
                param_18 = _e229;
                param_19 = max(dot(_e225, _e226), 0f);
                let _e230 = above_2;
                param_20 = _e230;
                let _e231 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_18), (&param_19), (&param_20));
                param_21 = _e231;
                let _e232 = mxc_mean_u0028_vf3_u003b((&param_21));
                fr = _e232;
                let _e233 = p;
                let _e234 = (*l_3);
                param_22 = _e234;
                let _e235 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_22));
                phi_2830_ = _e235;
                if _e235 {
                    let _e237 = (*l_3).mode;
                    phi_2830_ = ((_e237 & 1i) != 0i);
                }
                let _e241 = phi_2830_;
                let _e242 = fr;
                return (_e233 * select(1f, _e242, _e241));
            }
            return 0f;
        }
        default: {
            let _e172 = (*wo_1)[2u];
            let _e173 = (_e172 > 0f);
            phi_2749_ = _e173;
            if _e173 {
                let _e175 = (*wi)[2u];
                phi_2749_ = (_e175 > 0f);
            }
            let _e178 = phi_2749_;
            if _e178 {
                let _e180 = (*wi)[2u];
                local_3 = (_e180 * 0.31830987f);
            } else {
                local_3 = 0f;
            }
            let _e182 = local_3;
            return _e182;
        }
    }
}

fn mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b(sigma: ptr<function, f32>, wo_2: ptr<function, vec3<f32>>, wi_1: ptr<function, vec3<f32>>) -> f32 {
    var a: f32;
    var s_1: f32;
    var t: f32;
    var local_4: f32;

    let _e155 = (*sigma);
    a = (1f / (1f + (0.2877934f * _e155)));
    let _e159 = (*wi_1);
    let _e160 = (*wo_2);
    let _e163 = (*wi_1)[2u];
    let _e165 = (*wo_2)[2u];
    s_1 = (dot(_e159, _e160) - (_e163 * _e165));
    let _e168 = s_1;
    if (_e168 > 0f) {
        let _e171 = (*wi_1)[2u];
        let _e173 = (*wo_2)[2u];
        local_4 = max(max(_e171, _e173), 0.000001f);
    } else {
        local_4 = 1f;
    }
    let _e176 = local_4;
    t = _e176;
    let _e177 = a;
    let _e178 = (*sigma);
    let _e179 = a;
    let _e181 = s_1;
    let _e183 = t;
    return ((_e177 + (((_e178 * _e179) * _e181) / _e183)) * 0.31830987f);
}

fn mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b(wo_3: ptr<function, vec3<f32>>, wi_2: ptr<function, vec3<f32>>, alpha_6: ptr<function, vec2<f32>>) -> f32 {
    var param_23: vec3<f32>;
    var param_24: vec2<f32>;
    var param_25: vec3<f32>;
    var param_26: vec2<f32>;

    let _e155 = (*wo_3);
    param_23 = _e155;
    let _e156 = (*alpha_6);
    param_24 = _e156;
    let _e157 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_23), (&param_24));
    let _e159 = (*wi_2);
    param_25 = _e159;
    let _e160 = (*alpha_6);
    param_26 = _e160;
    let _e161 = mxc_ggx_lambda_u0028_vf3_u003b_vf2_u003b((&param_25), (&param_26));
    return (1f / ((1f + _e157) + _e161));
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
    var phi_2016_: bool;
    var phi_2023_: bool;

    let _e163 = (*wo_4)[2u];
    let _e164 = (_e163 <= 0f);
    phi_2016_ = _e164;
    if !(_e164) {
        let _e167 = (*wi_3)[2u];
        phi_2016_ = (_e167 <= 0f);
    }
    let _e170 = phi_2016_;
    phi_2023_ = _e170;
    if !(_e170) {
        let _e173 = (*l_4).alpha;
        param_27 = _e173;
        let _e174 = mxc_is_delta_u0028_vf2_u003b((&param_27));
        phi_2023_ = _e174;
    }
    let _e176 = phi_2023_;
    if _e176 {
        return vec3<f32>(0f, 0f, 0f);
    }
    let _e177 = (*wo_4);
    let _e178 = (*wi_3);
    h_1 = normalize((_e177 + _e178));
    let _e181 = (*wo_4);
    let _e182 = h_1;
    let _e185 = (*l_4);
    param_28 = _e185;
    param_29 = max(dot(_e181, _e182), 0f);
    param_30 = true;
    let _e186 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_28), (&param_29), (&param_30));
    f_1 = _e186;
    let _e188 = (*l_4).kind;
    if (_e188 == 1i) {
        let _e191 = (*l_4).c0_;
        let _e192 = f_1;
        f_1 = (_e192 * _e191);
    }
    let _e194 = f_1;
    let _e195 = h_1;
    param_31 = _e195;
    let _e197 = (*l_4).alpha;
    param_32 = _e197;
    let _e198 = mxc_ggx_d_u0028_vf3_u003b_vf2_u003b((&param_31), (&param_32));
    let _e200 = (*wo_4);
    param_33 = _e200;
    let _e201 = (*wi_3);
    param_34 = _e201;
    let _e203 = (*l_4).alpha;
    param_35 = _e203;
    let _e204 = mxc_ggx_g2_u0028_vf3_u003b_vf3_u003b_vf2_u003b((&param_33), (&param_34), (&param_35));
    let _e207 = (*wo_4)[2u];
    return (((_e194 * _e198) * _e204) / vec3((4f * _e207)));
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
    var phi_2682_: bool;
    var phi_2697_: bool;

    let _e166 = (*l_5).kind;
    switch _e166 {
        case 1: {
            let _e168 = (*wo_5)[2u];
            let _e170 = (*wi_4)[2u];
            if ((_e168 * _e170) > 0f) {
                let _e174 = (*l_5).mode;
                if ((_e174 & 1i) == 0i) {
                    return vec3<f32>(0f, 0f, 0f);
                }
                let _e178 = (*wo_5)[2u];
                if (_e178 < 0f) {
                    let _e180 = (*l_5);
                    m_2 = _e180;
                    let _e182 = (*l_5).eta;
                    m_2.eta = (1f / _e182);
                    m_2.c0_ = vec3<f32>(1f, 1f, 1f);
                    let _e186 = (*wo_5);
                    let _e188 = (*wi_4);
                    let _e190 = m_2;
                    param_36 = _e190;
                    param_37 = -(_e186);
                    param_38 = -(_e188);
                    let _e191 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_36), (&param_37), (&param_38));
                    return _e191;
                }
                let _e192 = (*l_5);
                param_39 = _e192;
                let _e193 = (*wo_5);
                param_40 = _e193;
                let _e194 = (*wi_4);
                param_41 = _e194;
                let _e195 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_39), (&param_40), (&param_41));
                return _e195;
            }
            return vec3<f32>(0f, 0f, 0f);
        }
        case 3, 2: {
            let _e197 = (*l_5).kind;
            let _e198 = (_e197 == 3i);
            phi_2682_ = _e198;
            if _e198 {
                let _e200 = (*l_5).mode;
                phi_2682_ = ((_e200 & 1i) == 0i);
            }
            let _e204 = phi_2682_;
            if _e204 {
                return vec3<f32>(0f, 0f, 0f);
            }
            let _e205 = (*l_5);
            param_42 = _e205;
            let _e206 = (*wo_5);
            param_43 = _e206;
            let _e207 = (*wi_4);
            param_44 = _e207;
            let _e208 = mxc_microfacet_reflect_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_42), (&param_43), (&param_44));
            return _e208;
        }
        case 4: {
            let _e210 = (*wo_5)[2u];
            let _e211 = (_e210 > 0f);
            phi_2697_ = _e211;
            if _e211 {
                let _e213 = (*wi_4)[2u];
                phi_2697_ = (_e213 > 0f);
            }
            let _e216 = phi_2697_;
            if _e216 {
                let _e218 = (*l_5).c0_;
                let _e220 = (*l_5).p0_;
                param_45 = _e220;
                let _e221 = (*wo_5);
                param_46 = _e221;
                let _e222 = (*wi_4);
                param_47 = _e222;
                let _e223 = mxc_fon_u0028_f1_u003b_vf3_u003b_vf3_u003b((&param_45), (&param_46), (&param_47));
                let _e226 = (*wi_4)[2u];
                local_5 = ((_e218 * _e223) * _e226);
            } else {
                local_5 = vec3<f32>(0f, 0f, 0f);
            }
            let _e228 = local_5;
            return _e228;
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
    let _e150 = (*v_2);
    let _e152 = (*frame)[0];
    let _e154 = (*v_2);
    let _e156 = (*frame)[1];
    let _e158 = (*v_2);
    let _e160 = (*frame)[2];
    return vec3<f32>(dot(_e150, _e152), dot(_e154, _e156), dot(_e158, _e160));
}

fn mxc_frame_u0028_vf3_u003b_vf3_u003b(N: ptr<function, vec3<f32>>, T: ptr<function, vec3<f32>>) -> mat3x3<f32> {
    var t_1: vec3<f32>;
    var l2_: f32;
    var s_2: f32;
    var a_1: f32;
    var b: f32;

    let _e155 = (*T);
    let _e156 = (*N);
    let _e157 = (*N);
    let _e158 = (*T);
    t_1 = (_e155 - (_e156 * dot(_e157, _e158)));
    let _e162 = t_1;
    let _e163 = t_1;
    l2_ = dot(_e162, _e163);
    let _e165 = l2_;
    if !((_e165 > 0.000000000001f)) {
        let _e169 = (*N)[2u];
        s_2 = select(-1f, 1f, (_e169 >= 0f));
        let _e172 = s_2;
        let _e174 = (*N)[2u];
        a_1 = (-1f / (_e172 + _e174));
        let _e178 = (*N)[0u];
        let _e180 = (*N)[1u];
        let _e182 = a_1;
        b = ((_e178 * _e180) * _e182);
        let _e184 = s_2;
        let _e186 = (*N)[0u];
        let _e189 = (*N)[0u];
        let _e191 = a_1;
        let _e194 = s_2;
        let _e195 = b;
        let _e197 = s_2;
        let _e200 = (*N)[0u];
        t_1 = vec3<f32>((1f + (((_e184 * _e186) * _e189) * _e191)), (_e194 * _e195), (-(_e197) * _e200));
    } else {
        let _e203 = l2_;
        let _e205 = t_1;
        t_1 = (_e205 * inverseSqrt(_e203));
    }
    let _e207 = t_1;
    let _e208 = (*N);
    let _e209 = t_1;
    let _e210 = cross(_e208, _e209);
    let _e211 = (*N);
    return mat3x3<f32>(vec3<f32>(_e207.x, _e207.y, _e207.z), vec3<f32>(_e210.x, _e210.y, _e210.z), vec3<f32>(_e211.x, _e211.y, _e211.z));
}

fn mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b(c_2: ptr<function, MxcClosure>, wo_6: ptr<function, vec3<f32>>, wi_5: ptr<function, vec3<f32>>, wantPdf: ptr<function, bool>, pdf: ptr<function, f32>) -> vec3<f32> {
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
    var ms: vec3<f32>;
    var local_6: vec3<f32>;
    var param_54: MxcLobe;
    var param_55: f32;
    var param_56: MxcLobe;
    var param_57: vec3<f32>;
    var param_58: vec3<f32>;
    var param_59: MxcLobe;
    var param_60: vec3<f32>;
    var param_61: vec3<f32>;
    var local_7: f32;

    f_2 = vec3<f32>(0f, 0f, 0f);
    p_1 = 0f;
    k = 0i;
    loop {
        let _e177 = k;
        let _e179 = (*c_2).count;
        if (_e177 < _e179) {
            let _e181 = k;
            let _e184 = (*c_2).lobes[_e181];
            l_7 = _e184;
            let _e186 = l_7.weight;
            if all((_e186 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e190 = l_7.N;
            param_48 = _e190;
            let _e192 = l_7.T;
            param_49 = _e192;
            let _e193 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_48), (&param_49));
            frame_1 = _e193;
            let _e194 = frame_1;
            param_50 = _e194;
            let _e195 = (*wo_6);
            param_51 = _e195;
            let _e196 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_50), (&param_51));
            o_1 = _e196;
            let _e197 = frame_1;
            param_52 = _e197;
            let _e198 = (*wi_5);
            param_53 = _e198;
            let _e199 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_52), (&param_53));
            i_1 = _e199;
            let _e201 = o_1[2u];
            let _e203 = i_1[2u];
            if ((_e201 * _e203) < 0f) {
                let _e206 = k;
                let _e209 = (*c_2).msT[_e206];
                local_6 = vec3(_e209);
            } else {
                let _e211 = k;
                let _e214 = (*c_2).ms[_e211];
                local_6 = _e214;
            }
            let _e215 = local_6;
            ms = _e215;
            let _e217 = l_7.weight;
            let _e218 = ms;
            let _e221 = i_1[2u];
            let _e223 = l_7;
            param_54 = _e223;
            param_55 = abs(_e221);
            let _e224 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_54), (&param_55));
            let _e226 = l_7;
            param_56 = _e226;
            let _e227 = o_1;
            param_57 = _e227;
            let _e228 = i_1;
            param_58 = _e228;
            let _e229 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_56), (&param_57), (&param_58));
            let _e231 = f_2;
            f_2 = (_e231 + (((_e217 * _e218) * _e224) * _e229));
            let _e233 = (*wantPdf);
            if _e233 {
                let _e234 = k;
                let _e237 = (*c_2).choice[_e234];
                let _e238 = l_7;
                param_59 = _e238;
                let _e239 = o_1;
                param_60 = _e239;
                let _e240 = i_1;
                param_61 = _e240;
                let _e241 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_59), (&param_60), (&param_61));
                let _e243 = p_1;
                p_1 = (_e243 + (_e237 * _e241));
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e245 = k;
            k = (_e245 + 1i);
        }
    }
    let _e248 = (*c_2).choiceTotal;
    if (_e248 > 0f) {
        let _e250 = p_1;
        let _e252 = (*c_2).choiceTotal;
        local_7 = (_e250 / _e252);
    } else {
        local_7 = 0f;
    }
    let _e254 = local_7;
    (*pdf) = _e254;
    let _e255 = f_2;
    return _e255;
}

fn mxc_env_to_world_u0028_vf3_u003b_f1_u003b(m_3: ptr<function, vec3<f32>>, angle: ptr<function, f32>) -> vec3<f32> {
    var c_3: f32;
    var s_3: f32;

    let _e152 = (*angle);
    c_3 = cos(_e152);
    let _e154 = (*angle);
    s_3 = sin(_e154);
    let _e156 = c_3;
    let _e158 = (*m_3)[0u];
    let _e160 = s_3;
    let _e162 = (*m_3)[2u];
    let _e166 = (*m_3)[1u];
    let _e167 = s_3;
    let _e170 = (*m_3)[0u];
    let _e172 = c_3;
    let _e174 = (*m_3)[2u];
    return vec3<f32>(((_e156 * _e158) + (_e160 * _e162)), _e166, ((-(_e167) * _e170) + (_e172 * _e174)));
}

fn mxc_safe_sqrt_u0028_f1_u003b(x_1: ptr<function, f32>) -> f32 {
    let _e149 = (*x_1);
    return sqrt(max(_e149, 0f));
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

    let _e163 = unnamed.mxc_env_size;
    size = max(_e163.xy, vec2<u32>(1u, 1u));
    let _e167 = size[0u];
    let _e169 = size[1u];
    n = (_e167 * _e169);
    let _e172 = (*u)[0u];
    let _e173 = n;
    let _e177 = n;
    k_1 = min(u32((_e172 * f32(_e173))), (_e177 - 1u));
    let _e180 = k_1;
    let _e183 = unnamed.mxc_env_cells[_e180];
    cell = _e183;
    let _e185 = (*u)[1u];
    let _e187 = cell[0u];
    if (_e185 >= _e187) {
        let _e190 = cell[1u];
        let _e192 = n;
        k_1 = min(bitcast<u32>(_e190), (_e192 - 1u));
    }
    let _e195 = k_1;
    let _e199 = unnamed.mxc_env_cells[_e195][2u];
    (*pdf_1) = _e199;
    let _e200 = k_1;
    let _e202 = size[0u];
    i_2 = (_e200 % _e202);
    let _e204 = k_1;
    let _e206 = size[0u];
    j = (_e204 / _e206);
    let _e208 = i_2;
    let _e211 = (*u)[2u];
    let _e214 = size[0u];
    phi = (6.2831855f * (((f32(_e208) + _e211) / f32(_e214)) - 0.5f));
    let _e219 = j;
    let _e223 = size[1u];
    y0_ = cos(((3.1415927f * f32(_e219)) / f32(_e223)));
    let _e227 = j;
    let _e232 = size[1u];
    y1_ = cos(((3.1415927f * f32((_e227 + 1u))) / f32(_e232)));
    let _e236 = y0_;
    let _e237 = y1_;
    let _e239 = (*u)[3u];
    y = mix(_e236, _e237, _e239);
    let _e241 = y;
    let _e242 = y;
    param_62 = (1f - (_e241 * _e242));
    let _e245 = mxc_safe_sqrt_u0028_f1_u003b((&param_62));
    r = _e245;
    let _e246 = r;
    let _e247 = phi;
    let _e250 = y;
    let _e251 = r;
    let _e253 = phi;
    return vec3<f32>((_e246 * sin(_e247)), _e250, (-(_e251) * cos(_e253)));
}

fn mxc_power_heuristic_u0028_f1_u003b_f1_u003b(a_2: ptr<function, f32>, b_1: ptr<function, f32>) -> f32 {
    var a2_1: f32;
    var b2_: f32;
    var local_8: f32;

    let _e153 = (*a_2);
    let _e154 = (*a_2);
    a2_1 = (_e153 * _e154);
    let _e156 = (*b_1);
    let _e157 = (*b_1);
    b2_ = (_e156 * _e157);
    let _e159 = a2_1;
    let _e160 = b2_;
    if ((_e159 + _e160) > 0f) {
        let _e163 = a2_1;
        let _e164 = a2_1;
        let _e165 = b2_;
        local_8 = (_e163 / (_e164 + _e165));
    } else {
        local_8 = 0f;
    }
    let _e168 = local_8;
    return _e168;
}

fn mxc_env_uv_u0028_vf3_u003b(d_1: ptr<function, vec3<f32>>) -> vec2<f32> {
    var u_1: f32;
    var local_9: f32;
    var v_3: f32;

    let _e153 = (*d_1)[0u];
    let _e156 = (*d_1)[2u];
    if ((abs(_e153) + abs(_e156)) > 0.000000000001f) {
        let _e161 = (*d_1)[0u];
        let _e163 = (*d_1)[2u];
        local_9 = (0.5f + (atan2(_e161, -(_e163)) * 0.15915494f));
    } else {
        local_9 = 0.5f;
    }
    let _e168 = local_9;
    u_1 = _e168;
    let _e169 = (*d_1);
    let _e173 = (*d_1)[1u];
    v_3 = (atan2(length(_e169.xz), _e173) * 0.31830987f);
    let _e176 = u_1;
    let _e177 = v_3;
    return vec2<f32>(_e176, _e177);
}

fn mxc_env_cell_u0028_vf3_u003b(d_2: ptr<function, vec3<f32>>) -> u32 {
    var uv: vec2<f32>;
    var param_63: vec3<f32>;
    var size_1: vec2<u32>;
    var i_3: u32;
    var j_1: u32;

    let _e154 = (*d_2);
    param_63 = _e154;
    let _e155 = mxc_env_uv_u0028_vf3_u003b((&param_63));
    uv = _e155;
    let _e157 = unnamed.mxc_env_size;
    size_1 = max(_e157.xy, vec2<u32>(1u, 1u));
    let _e161 = uv[0u];
    let _e164 = size_1[0u];
    let _e169 = size_1[0u];
    i_3 = min(u32((max(_e161, 0f) * f32(_e164))), (_e169 - 1u));
    let _e173 = uv[1u];
    let _e176 = size_1[1u];
    let _e181 = size_1[1u];
    j_1 = min(u32((max(_e173, 0f) * f32(_e176))), (_e181 - 1u));
    let _e184 = j_1;
    let _e186 = size_1[0u];
    let _e188 = i_3;
    return ((_e184 * _e186) + _e188);
}

fn mxc_env_pdf_u0028_vf3_u003b(d_3: ptr<function, vec3<f32>>) -> f32 {
    var param_64: vec3<f32>;

    let _e150 = (*d_3);
    param_64 = _e150;
    let _e151 = mxc_env_cell_u0028_vf3_u003b((&param_64));
    let _e155 = unnamed.mxc_env_cells[_e151][2u];
    return _e155;
}

fn mxc_env_to_map_u0028_vf3_u003b_f1_u003b(w: ptr<function, vec3<f32>>, angle_1: ptr<function, f32>) -> vec3<f32> {
    var c_4: f32;
    var s_4: f32;

    let _e152 = (*angle_1);
    c_4 = cos(_e152);
    let _e154 = (*angle_1);
    s_4 = sin(_e154);
    let _e156 = c_4;
    let _e158 = (*w)[0u];
    let _e160 = s_4;
    let _e162 = (*w)[2u];
    let _e166 = (*w)[1u];
    let _e167 = s_4;
    let _e169 = (*w)[0u];
    let _e171 = c_4;
    let _e173 = (*w)[2u];
    return vec3<f32>(((_e156 * _e158) - (_e160 * _e162)), _e166, ((_e167 * _e169) + (_e171 * _e173)));
}

fn mxc_env_lookup_u0028_vf3_u003b(d_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_65: vec3<f32>;

    let _e150 = (*d_4);
    param_65 = _e150;
    let _e151 = mxc_env_uv_u0028_vf3_u003b((&param_65));
    let _e152 = textureSampleLevel(mxc_env_radiance_texture, mxc_env_radiance_sampler, _e151, 0f);
    return _e152.xyz;
}

fn mxc_sky_u0028_vf3_u003b(d_5: ptr<function, vec3<f32>>) -> vec3<f32> {
    var y_1: f32;
    var horizon: vec3<f32>;
    var zenith: vec3<f32>;
    var ground: vec3<f32>;

    let _e154 = (*d_5)[1u];
    y_1 = clamp(_e154, -1f, 1f);
    horizon = vec3<f32>(1f, 0.96f, 0.9f);
    zenith = vec3<f32>(0.3f, 0.5f, 0.95f);
    ground = vec3<f32>(0.16f, 0.145f, 0.13f);
    let _e156 = y_1;
    if (_e156 >= 0f) {
        let _e158 = horizon;
        let _e159 = zenith;
        let _e160 = y_1;
        return mix(_e158, _e159, vec3(sqrt(_e160)));
    }
    let _e164 = horizon;
    let _e165 = ground;
    let _e166 = y_1;
    return mix(_e164, _e165, vec3(sqrt(-(_e166))));
}

fn mxc_environment_code_u0028_() -> i32 {
    var local_10: i32;

    if false {
        local_10 = MXC_ENVIRONMENT;
    } else {
        let _e151 = mxc_view.counts[1u];
        local_10 = _e151;
    }
    let _e152 = local_10;
    return _e152;
}

fn mxc_environment_u0028_vf3_u003b(d_6: ptr<function, vec3<f32>>) -> vec3<f32> {
    var code: i32;
    var param_66: vec3<f32>;
    var param_67: vec3<f32>;
    var param_68: f32;
    var param_69: vec3<f32>;

    let _e154 = mxc_environment_code_u0028_();
    code = _e154;
    let _e155 = code;
    if (_e155 == 1i) {
        let _e159 = mxc_view.environment[0u];
        return vec3(_e159);
    }
    let _e161 = code;
    if (_e161 == 2i) {
        let _e165 = mxc_view.environment[0u];
        let _e166 = (*d_6);
        param_66 = _e166;
        let _e167 = mxc_sky_u0028_vf3_u003b((&param_66));
        return (_e167 * _e165);
    }
    let _e169 = code;
    if (_e169 == 3i) {
        let _e173 = mxc_view.environment[0u];
        let _e174 = (*d_6);
        param_67 = _e174;
        let _e177 = mxc_view.environment[2u];
        param_68 = _e177;
        let _e178 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_67), (&param_68));
        param_69 = _e178;
        let _e179 = mxc_env_lookup_u0028_vf3_u003b((&param_69));
        return (_e179 * _e173);
    }
    return vec3<f32>(0f, 0f, 0f);
}

fn mxc_exit_direction_u0028_vf3_u003b_vf3_u003b(d_7: ptr<function, vec3<f32>>, t_2: ptr<function, vec3<f32>>) -> vec3<f32> {
    var axis: vec3<f32>;
    var s_5: f32;
    var c_5: f32;

    let _e153 = (*d_7);
    let _e154 = (*t_2);
    axis = cross(_e153, _e154);
    let _e156 = axis;
    s_5 = length(_e156);
    let _e158 = s_5;
    if (_e158 < 0.000001f) {
        let _e160 = (*t_2);
        return _e160;
    }
    let _e161 = s_5;
    let _e162 = axis;
    axis = (_e162 / vec3(_e161));
    let _e165 = (*d_7);
    let _e166 = (*t_2);
    c_5 = dot(_e165, _e166);
    let _e168 = (*t_2);
    let _e169 = c_5;
    let _e171 = axis;
    let _e172 = (*t_2);
    let _e174 = s_5;
    let _e177 = axis;
    let _e178 = axis;
    let _e179 = (*t_2);
    let _e182 = c_5;
    return (((_e168 * _e169) + (cross(_e171, _e172) * _e174)) + ((_e177 * dot(_e178, _e179)) * (1f - _e182)));
}

fn mxc_to_world_u0028_mf33_u003b_vf3_u003b(frame_2: ptr<function, mat3x3<f32>>, v_4: ptr<function, vec3<f32>>) -> vec3<f32> {
    let _e151 = (*frame_2)[0];
    let _e153 = (*v_4)[0u];
    let _e156 = (*frame_2)[1];
    let _e158 = (*v_4)[1u];
    let _e162 = (*frame_2)[2];
    let _e164 = (*v_4)[2u];
    return (((_e151 * _e153) + (_e156 * _e158)) + (_e162 * _e164));
}

fn mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b(wo_7: ptr<function, vec3<f32>>, alpha_7: ptr<function, vec2<f32>>, u_2: ptr<function, vec2<f32>>) -> vec3<f32> {
    var param_70: vec2<f32>;
    var vh: vec3<f32>;
    var lensq: f32;
    var t1_: vec3<f32>;
    var local_11: vec3<f32>;
    var t2_: vec3<f32>;
    var r_1: f32;
    var phi_1: f32;
    var p1_: f32;
    var p2_: f32;
    var s_6: f32;
    var param_71: f32;
    var nh: vec3<f32>;
    var param_72: f32;

    let _e165 = (*alpha_7);
    param_70 = _e165;
    let _e166 = mxc_rough_alpha_u0028_vf2_u003b((&param_70));
    (*alpha_7) = _e166;
    let _e168 = (*alpha_7)[0u];
    let _e170 = (*wo_7)[0u];
    let _e173 = (*alpha_7)[1u];
    let _e175 = (*wo_7)[1u];
    let _e178 = (*wo_7)[2u];
    vh = normalize(vec3<f32>((_e168 * _e170), (_e173 * _e175), _e178));
    let _e182 = vh[0u];
    let _e184 = vh[0u];
    let _e187 = vh[1u];
    let _e189 = vh[1u];
    lensq = ((_e182 * _e184) + (_e187 * _e189));
    let _e192 = lensq;
    if (_e192 > 0f) {
        let _e195 = vh[1u];
        let _e198 = vh[0u];
        let _e200 = lensq;
        local_11 = (vec3<f32>(-(_e195), _e198, 0f) * inverseSqrt(_e200));
    } else {
        local_11 = vec3<f32>(1f, 0f, 0f);
    }
    let _e203 = local_11;
    t1_ = _e203;
    let _e204 = vh;
    let _e205 = t1_;
    t2_ = cross(_e204, _e205);
    let _e208 = (*u_2)[0u];
    r_1 = sqrt(_e208);
    let _e211 = (*u_2)[1u];
    phi_1 = (6.2831855f * _e211);
    let _e213 = r_1;
    let _e214 = phi_1;
    p1_ = (_e213 * cos(_e214));
    let _e217 = r_1;
    let _e218 = phi_1;
    p2_ = (_e217 * sin(_e218));
    let _e222 = vh[2u];
    s_6 = (0.5f * (1f + _e222));
    let _e225 = s_6;
    let _e227 = p1_;
    let _e228 = p1_;
    param_71 = (1f - (_e227 * _e228));
    let _e231 = mxc_safe_sqrt_u0028_f1_u003b((&param_71));
    let _e233 = s_6;
    let _e234 = p2_;
    p2_ = (((1f - _e225) * _e231) + (_e233 * _e234));
    let _e237 = p1_;
    let _e238 = t1_;
    let _e240 = p2_;
    let _e241 = t2_;
    let _e244 = p1_;
    let _e245 = p1_;
    let _e248 = p2_;
    let _e249 = p2_;
    param_72 = ((1f - (_e244 * _e245)) - (_e248 * _e249));
    let _e252 = mxc_safe_sqrt_u0028_f1_u003b((&param_72));
    let _e253 = vh;
    nh = (((_e238 * _e237) + (_e241 * _e240)) + (_e253 * _e252));
    let _e257 = (*alpha_7)[0u];
    let _e259 = nh[0u];
    let _e262 = (*alpha_7)[1u];
    let _e264 = nh[1u];
    let _e267 = nh[2u];
    return normalize(vec3<f32>((_e257 * _e259), (_e262 * _e264), max(_e267, 0f)));
}

fn mxc_sample_cosine_u0028_vf2_u003b(u_3: ptr<function, vec2<f32>>) -> vec3<f32> {
    var r_2: f32;
    var phi_2: f32;
    var param_73: f32;

    let _e153 = (*u_3)[0u];
    r_2 = sqrt(_e153);
    let _e156 = (*u_3)[1u];
    phi_2 = (6.2831855f * _e156);
    let _e158 = r_2;
    let _e159 = phi_2;
    let _e162 = r_2;
    let _e163 = phi_2;
    let _e167 = (*u_3)[0u];
    param_73 = (1f - _e167);
    let _e169 = mxc_safe_sqrt_u0028_f1_u003b((&param_73));
    return vec3<f32>((_e158 * cos(_e159)), (_e162 * sin(_e163)), _e169);
}

fn mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_8: ptr<function, MxcLobe>, wo_8: ptr<function, vec3<f32>>, u_4: ptr<function, vec3<f32>>) -> MxcLobeSample {
    var s_7: MxcLobeSample;
    var above_3: bool;
    var o_2: vec3<f32>;
    var local_12: vec3<f32>;
    var delta: bool;
    var param_74: vec2<f32>;
    var m_4: vec3<f32>;
    var local_13: vec3<f32>;
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
    var local_14: f32;
    var param_82: vec3<f32>;
    var pReflect: f32;
    var local_15: f32;
    var i_4: vec3<f32>;
    var local_16: vec3<f32>;
    var tint: vec3<f32>;
    var local_17: vec3<f32>;
    var local_18: vec3<f32>;
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
    var phi_2961_: bool;
    var phi_2966_: bool;
    var phi_2977_: bool;

    s_7.valid = false;
    s_7.delta = false;
    s_7.pdf = 0f;
    s_7.value = vec3<f32>(0f, 0f, 0f);
    s_7.wi = vec3<f32>(0f, 0f, 1f);
    let _e199 = (*l_8).kind;
    switch _e199 {
        case 2, 3, 1: {
            let _e226 = (*wo_8)[2u];
            above_3 = (_e226 > 0f);
            let _e228 = above_3;
            if _e228 {
                let _e229 = (*wo_8);
                local_12 = _e229;
            } else {
                let _e230 = (*wo_8);
                local_12 = -(_e230);
            }
            let _e232 = local_12;
            o_2 = _e232;
            let _e234 = o_2[2u];
            if (_e234 <= 0f) {
                let _e236 = s_7;
                return _e236;
            }
            let _e238 = (*l_8).alpha;
            param_74 = _e238;
            let _e239 = mxc_is_delta_u0028_vf2_u003b((&param_74));
            delta = _e239;
            let _e240 = delta;
            if _e240 {
                local_13 = vec3<f32>(0f, 0f, 1f);
            } else {
                let _e241 = o_2;
                param_75 = _e241;
                let _e243 = (*l_8).alpha;
                param_76 = _e243;
                let _e244 = (*u_4);
                param_77 = _e244.xy;
                let _e246 = mxc_ggx_sample_vndf_u0028_vf3_u003b_vf2_u003b_vf2_u003b((&param_75), (&param_76), (&param_77));
                local_13 = _e246;
            }
            let _e247 = local_13;
            m_4 = _e247;
            let _e248 = o_2;
            let _e249 = m_4;
            hm = dot(_e248, _e249);
            let _e252 = (*l_8).kind;
            let _e253 = (_e252 == 1i);
            phi_2961_ = _e253;
            if !(_e253) {
                let _e256 = (*l_8).kind;
                phi_2961_ = (_e256 == 3i);
            }
            let _e259 = phi_2961_;
            phi_2966_ = _e259;
            if _e259 {
                let _e260 = (*l_8);
                param_78 = _e260;
                let _e261 = mxc_lobe_transmits_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_78));
                phi_2966_ = _e261;
            }
            let _e263 = phi_2966_;
            transmits = _e263;
            let _e265 = (*l_8).kind;
            let _e266 = (_e265 == 2i);
            phi_2977_ = _e266;
            if !(_e266) {
                let _e269 = (*l_8).mode;
                phi_2977_ = ((_e269 & 1i) != 0i);
            }
            let _e273 = phi_2977_;
            reflects = _e273;
            let _e274 = hm;
            let _e276 = (*l_8);
            param_79 = _e276;
            param_80 = max(_e274, 0f);
            let _e277 = above_3;
            param_81 = _e277;
            let _e278 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_79), (&param_80), (&param_81));
            f_3 = _e278;
            let _e279 = transmits;
            if _e279 {
                let _e280 = f_3;
                param_82 = _e280;
                let _e281 = mxc_mean_u0028_vf3_u003b((&param_82));
                local_14 = _e281;
            } else {
                local_14 = 1f;
            }
            let _e282 = local_14;
            fr_1 = _e282;
            let _e283 = transmits;
            if _e283 {
                let _e284 = reflects;
                let _e285 = fr_1;
                local_15 = select(0f, _e285, _e284);
            } else {
                local_15 = 1f;
            }
            let _e287 = local_15;
            pReflect = _e287;
            let _e289 = (*u_4)[2u];
            let _e290 = pReflect;
            if (_e289 < _e290) {
                let _e292 = o_2;
                let _e294 = m_4;
                i_4 = reflect(-(_e292), _e294);
                let _e297 = i_4[2u];
                if (_e297 <= 0f) {
                    let _e299 = s_7;
                    return _e299;
                }
                let _e300 = above_3;
                if _e300 {
                    let _e301 = i_4;
                    local_16 = _e301;
                } else {
                    let _e302 = i_4;
                    local_16 = -(_e302);
                }
                let _e304 = local_16;
                s_7.wi = _e304;
                let _e306 = delta;
                s_7.delta = _e306;
                let _e308 = delta;
                if _e308 {
                    let _e310 = (*l_8).kind;
                    if (_e310 == 1i) {
                        let _e312 = above_3;
                        if _e312 {
                            let _e314 = (*l_8).c0_;
                            local_18 = _e314;
                        } else {
                            local_18 = vec3<f32>(1f, 1f, 1f);
                        }
                        let _e315 = local_18;
                        local_17 = _e315;
                    } else {
                        local_17 = vec3<f32>(1f, 1f, 1f);
                    }
                    let _e316 = local_17;
                    tint = _e316;
                    let _e317 = f_3;
                    let _e318 = tint;
                    s_7.value = (_e317 * _e318);
                    let _e321 = pReflect;
                    s_7.pdf = _e321;
                } else {
                    let _e323 = (*l_8);
                    param_83 = _e323;
                    let _e324 = (*wo_8);
                    param_84 = _e324;
                    let _e326 = s_7.wi;
                    param_85 = _e326;
                    let _e327 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_83), (&param_84), (&param_85));
                    s_7.value = _e327;
                    let _e329 = (*l_8);
                    param_86 = _e329;
                    let _e330 = (*wo_8);
                    param_87 = _e330;
                    let _e332 = s_7.wi;
                    param_88 = _e332;
                    let _e333 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_86), (&param_87), (&param_88));
                    s_7.pdf = _e333;
                }
                let _e336 = s_7.pdf;
                s_7.valid = (_e336 > 0f);
                let _e339 = s_7;
                return _e339;
            }
            let _e340 = s_7;
            return _e340;
        }
        default: {
            let _e201 = (*wo_8)[2u];
            if (_e201 <= 0f) {
                let _e203 = s_7;
                return _e203;
            }
            let _e204 = (*u_4);
            param_89 = _e204.xy;
            let _e206 = mxc_sample_cosine_u0028_vf2_u003b((&param_89));
            s_7.wi = _e206;
            let _e208 = (*l_8);
            param_90 = _e208;
            let _e209 = (*wo_8);
            param_91 = _e209;
            let _e211 = s_7.wi;
            param_92 = _e211;
            let _e212 = mxc_lobe_eval_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_90), (&param_91), (&param_92));
            s_7.value = _e212;
            let _e214 = (*l_8);
            param_93 = _e214;
            let _e215 = (*wo_8);
            param_94 = _e215;
            let _e217 = s_7.wi;
            param_95 = _e217;
            let _e218 = mxc_lobe_pdf_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_93), (&param_94), (&param_95));
            s_7.pdf = _e218;
            let _e221 = s_7.pdf;
            s_7.valid = (_e221 > 0f);
            let _e224 = s_7;
            return _e224;
        }
    }
}

fn mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b(c_6: ptr<function, MxcClosure>, wo_9: ptr<function, vec3<f32>>, u_5: ptr<function, vec3<f32>>) -> MxcSample {
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
    let _e182 = (*wo_9);
    s_8.wi = _e182;
    let _e185 = (*c_6).choiceTotal;
    total = _e185;
    let _e187 = (*c_6).count;
    let _e189 = total;
    if ((_e187 == 0i) || (_e189 <= 0f)) {
        let _e192 = s_8;
        return _e192;
    }
    let _e194 = (*u_5)[2u];
    let _e195 = total;
    x_2 = (_e194 * _e195);
    chosen = -1i;
    before = 0f;
    p_2 = 0f;
    lastBefore = 0f;
    last = -1i;
    k_2 = 0i;
    loop {
        let _e197 = k_2;
        let _e199 = (*c_6).count;
        if (_e197 < _e199) {
            let _e201 = k_2;
            let _e204 = (*c_6).choice[_e201];
            pk = _e204;
            let _e205 = pk;
            if (_e205 <= 0f) {
                continue;
            }
            let _e207 = x_2;
            let _e208 = before;
            let _e209 = pk;
            if (_e207 < (_e208 + _e209)) {
                let _e212 = k_2;
                chosen = _e212;
                let _e213 = pk;
                p_2 = _e213;
                break;
            }
            let _e214 = k_2;
            last = _e214;
            let _e215 = before;
            lastBefore = _e215;
            let _e216 = pk;
            let _e217 = before;
            before = (_e217 + _e216);
            continue;
        } else {
            break;
        }
        continuing {
            let _e219 = k_2;
            k_2 = (_e219 + 1i);
        }
    }
    let _e221 = chosen;
    if (_e221 < 0i) {
        let _e223 = last;
        chosen = max(_e223, 0i);
        let _e225 = chosen;
        let _e228 = (*c_6).choice[_e225];
        p_2 = _e228;
        let _e229 = lastBefore;
        before = _e229;
    }
    let _e230 = p_2;
    if (_e230 <= 0f) {
        let _e232 = s_8;
        return _e232;
    }
    let _e233 = x_2;
    let _e234 = before;
    let _e236 = p_2;
    uz = clamp(((_e233 - _e234) / _e236), 0f, 0.99999994f);
    let _e239 = chosen;
    let _e242 = (*c_6).lobes[_e239];
    l_9 = _e242;
    let _e244 = l_9.N;
    param_96 = _e244;
    let _e246 = l_9.T;
    param_97 = _e246;
    let _e247 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_96), (&param_97));
    frame_3 = _e247;
    let _e248 = frame_3;
    param_98 = _e248;
    let _e249 = (*wo_9);
    param_99 = _e249;
    let _e250 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_98), (&param_99));
    o_3 = _e250;
    let _e251 = (*u_5);
    let _e252 = _e251.xy;
    let _e253 = uz;
    let _e257 = l_9;
    param_100 = _e257;
    let _e258 = o_3;
    param_101 = _e258;
    param_102 = vec3<f32>(_e252.x, _e252.y, _e253);
    let _e259 = mxc_lobe_sample_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_100), (&param_101), (&param_102));
    ls = _e259;
    let _e261 = ls.valid;
    if !(_e261) {
        let _e263 = s_8;
        return _e263;
    }
    let _e264 = frame_3;
    param_103 = _e264;
    let _e266 = ls.wi;
    param_104 = _e266;
    let _e267 = mxc_to_world_u0028_mf33_u003b_vf3_u003b((&param_103), (&param_104));
    s_8.wi = _e267;
    let _e270 = ls.delta;
    if _e270 {
        s_8.delta = true;
        let _e273 = ls.pdf;
        let _e274 = p_2;
        let _e276 = total;
        s_8.pdf = ((_e273 * _e274) / _e276);
        let _e280 = l_9.weight;
        let _e281 = chosen;
        let _e284 = (*c_6).ms[_e281];
        let _e288 = ls.wi[2u];
        let _e290 = l_9;
        param_105 = _e290;
        param_106 = abs(_e288);
        let _e291 = mxc_lobe_absorption_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b((&param_105), (&param_106));
        let _e294 = ls.value;
        let _e297 = s_8.pdf;
        s_8.weight = ((((_e280 * _e284) * _e291) * _e294) / vec3(_e297));
        let _e302 = s_8.pdf;
        s_8.valid = (_e302 > 0f);
        let _e305 = s_8;
        return _e305;
    }
    s_8.evaluate = true;
    s_8.valid = true;
    let _e308 = s_8;
    return _e308;
}

fn mxc_radical_inverse_u0028_u1_u003b_u1_u003b(i_5: ptr<function, u32>, base: ptr<function, u32>) -> f32 {
    var inv: f32;
    var f_4: f32;
    var r_3: f32;

    let _e153 = (*base);
    if (_e153 == 2u) {
        let _e155 = (*i_5);
        return (f32((reverseBits(_e155) >> bitcast<u32>(8i))) * 0.000000059604645f);
    }
    let _e161 = (*base);
    inv = (1f / f32(_e161));
    let _e164 = inv;
    f_4 = _e164;
    r_3 = 0f;
    loop {
        let _e165 = (*i_5);
        if (_e165 > 0u) {
            let _e167 = f_4;
            let _e168 = (*i_5);
            let _e169 = (*base);
            let _e173 = r_3;
            r_3 = (_e173 + (_e167 * f32((_e168 % _e169))));
            let _e175 = inv;
            let _e176 = f_4;
            f_4 = (_e176 * _e175);
            continue;
        } else {
            break;
        }
        continuing {
            let _e178 = (*base);
            let _e179 = (*i_5);
            (*i_5) = (_e179 / _e178);
        }
    }
    let _e181 = r_3;
    return min(_e181, 0.99999994f);
}

fn mxc_pcg_u0028_u1_u003b(v_5: ptr<function, u32>) -> u32 {
    var state: u32;
    var word: u32;

    let _e151 = (*v_5);
    state = ((_e151 * 747796405u) + 2891336453u);
    let _e154 = state;
    let _e155 = state;
    let _e161 = state;
    word = (((_e154 >> bitcast<u32>(((_e155 >> bitcast<u32>(28u)) + 4u))) ^ _e161) * 277803737u);
    let _e164 = word;
    let _e167 = word;
    return ((_e164 >> bitcast<u32>(22u)) ^ _e167);
}

fn mxc_uniform_u0028_u1_u003b(seed: ptr<function, u32>) -> f32 {
    var param_107: u32;

    let _e150 = (*seed);
    param_107 = _e150;
    let _e151 = mxc_pcg_u0028_u1_u003b((&param_107));
    (*seed) = _e151;
    let _e152 = (*seed);
    return (f32((_e152 >> bitcast<u32>(8i))) * 0.000000059604645f);
}

fn mxc_light_kinds_u0028_() -> i32 {
    return 7i;
}

fn mxc_light_count_u0028_() -> i32 {
    var local_19: i32;

    if false {
        local_19 = MXC_LIGHT_COUNT;
    } else {
        let _e151 = mxc_view.counts[0u];
        local_19 = _e151;
    }
    let _e152 = local_19;
    return min(_e152, 8i);
}

fn mxc_fon_albedo_u0028_f1_u003b_f1_u003b(sigma_1: ptr<function, f32>, mu_1: ptr<function, f32>) -> f32 {
    var a_3: f32;
    var c_7: f32;
    var s_9: f32;
    var param_108: f32;
    var theta: f32;
    var tail: f32;
    var local_20: f32;
    var g: f32;

    let _e158 = (*sigma_1);
    a_3 = (1f / (1f + (0.2877934f * _e158)));
    let _e162 = (*mu_1);
    c_7 = clamp(_e162, 0f, 1f);
    let _e164 = c_7;
    let _e165 = c_7;
    param_108 = (1f - (_e164 * _e165));
    let _e168 = mxc_safe_sqrt_u0028_f1_u003b((&param_108));
    s_9 = _e168;
    let _e169 = c_7;
    theta = acos(_e169);
    let _e171 = c_7;
    if (_e171 > 0.0001f) {
        let _e173 = s_9;
        let _e174 = s_9;
        let _e176 = s_9;
        let _e179 = c_7;
        local_20 = ((1f - ((_e173 * _e174) * _e176)) / _e179);
    } else {
        let _e181 = c_7;
        local_20 = (1.5f * _e181);
    }
    let _e183 = local_20;
    tail = _e183;
    let _e184 = s_9;
    let _e185 = theta;
    let _e186 = s_9;
    let _e187 = c_7;
    let _e191 = s_9;
    let _e193 = tail;
    let _e196 = s_9;
    g = (((_e184 * (_e185 - (_e186 * _e187))) + ((0.6666667f * _e191) * _e193)) - (0.6666667f * _e196));
    let _e199 = a_3;
    let _e200 = (*sigma_1);
    let _e201 = a_3;
    let _e203 = g;
    return (_e199 + (((_e200 * _e201) * _e203) * 0.31830987f));
}

fn mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b(mu_2: ptr<function, f32>, x_3: ptr<function, f32>, firstRow: ptr<function, f32>) -> vec4<f32> {
    var t_3: vec2<f32>;

    let _e152 = (*mu_2);
    let _e155 = (*x_3);
    t_3 = ((vec2<f32>(sqrt(clamp(_e152, 0f, 1f)), clamp(_e155, 0f, 1f)) * 31f) + vec2(0.5f));
    let _e162 = t_3[0u];
    let _e164 = (*firstRow);
    let _e166 = t_3[1u];
    let _e170 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, vec2<f32>((_e162 / 32f), ((_e164 + _e166) / 2070f)), 0f);
    return _e170;
}

fn mxc_table_u0028_f1_u003b_f1_u003b(mu_3: ptr<function, f32>, x_4: ptr<function, f32>) -> vec4<f32> {
    var param_109: f32;
    var param_110: f32;
    var param_111: f32;

    let _e153 = (*mu_3);
    param_109 = _e153;
    let _e154 = (*x_4);
    param_110 = _e154;
    param_111 = 0f;
    let _e155 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_109), (&param_110), (&param_111));
    return _e155;
}

fn mxc_split_sum_u0028_f1_u003b_f1_u003b(mu_4: ptr<function, f32>, alpha_8: ptr<function, f32>) -> vec2<f32> {
    var param_112: f32;
    var param_113: f32;

    let _e152 = (*alpha_8);
    let _e155 = (*mu_4);
    param_112 = _e155;
    param_113 = sqrt(max(_e152, 0f));
    let _e156 = mxc_table_u0028_f1_u003b_f1_u003b((&param_112), (&param_113));
    return _e156.xy;
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

    let _e162 = (*e);
    s_10 = (sqrt(clamp((0.5f * (_e162 - 1f)), 0f, 1f)) * 31f);
    let _e168 = s_10;
    s0_ = min(floor(_e168), 30f);
    let _e171 = (*alpha_9);
    x_5 = sqrt(max(_e171, 0f));
    let _e174 = s0_;
    let _e177 = (*mu_5);
    param_114 = _e177;
    let _e178 = x_5;
    param_115 = _e178;
    param_116 = (32f * (1f + _e174));
    let _e179 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_114), (&param_115), (&param_116));
    a_4 = _e179;
    let _e180 = s0_;
    let _e183 = (*mu_5);
    param_117 = _e183;
    let _e184 = x_5;
    param_118 = _e184;
    param_119 = (32f * (2f + _e180));
    let _e185 = mxc_table_at_u0028_f1_u003b_f1_u003b_f1_u003b((&param_117), (&param_118), (&param_119));
    b_2 = _e185;
    let _e186 = a_4;
    let _e187 = b_2;
    let _e188 = s_10;
    let _e189 = s0_;
    return mix(_e186, _e187, vec4((_e188 - _e189)));
}

fn mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b(mu_6: ptr<function, f32>, alpha_10: ptr<function, f32>, eta_1: ptr<function, f32>) -> f32 {
    var e_1: f32;
    var local_21: f32;
    var param_120: f32;
    var param_121: f32;
    var param_122: f32;

    let _e156 = (*eta_1);
    if (_e156 >= 1f) {
        let _e158 = (*eta_1);
        local_21 = _e158;
    } else {
        let _e159 = (*eta_1);
        local_21 = (1f / max(_e159, 0.001f));
    }
    let _e162 = local_21;
    e_1 = _e162;
    let _e163 = (*mu_6);
    param_120 = _e163;
    let _e164 = (*alpha_10);
    param_121 = _e164;
    let _e165 = e_1;
    param_122 = _e165;
    let _e166 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_120), (&param_121), (&param_122));
    return _e166.x;
}

fn mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_10: ptr<function, MxcLobe>, wo_10: ptr<function, vec3<f32>>, ms_1: ptr<function, vec3<f32>>) -> vec3<f32> {
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
    var local_22: vec3<f32>;
    var param_135: vec2<f32>;
    var param_136: MxcLobe;
    var param_137: f32;
    var param_138: bool;
    var param_139: f32;
    var param_140: f32;
    var phi_2462_: bool;
    var phi_2469_: bool;
    var phi_2487_: bool;

    let _e178 = (*wo_10)[2u];
    mu_7 = clamp(_e178, 0f, 1f);
    let _e181 = (*l_10).kind;
    let _e182 = (_e181 == 1i);
    phi_2462_ = _e182;
    if !(_e182) {
        let _e185 = (*l_10).kind;
        phi_2462_ = (_e185 == 2i);
    }
    let _e188 = phi_2462_;
    phi_2469_ = _e188;
    if !(_e188) {
        let _e191 = (*l_10).kind;
        phi_2469_ = (_e191 == 3i);
    }
    let _e194 = phi_2469_;
    if _e194 {
        let _e197 = (*l_10).alpha[0u];
        let _e200 = (*l_10).alpha[1u];
        alpha_11 = sqrt((_e197 * _e200));
        let _e204 = (*l_10).kind;
        let _e205 = (_e204 == 1i);
        phi_2487_ = _e205;
        if _e205 {
            let _e207 = (*l_10).alpha;
            param_123 = _e207;
            let _e208 = mxc_is_delta_u0028_vf2_u003b((&param_123));
            phi_2487_ = !(_e208);
        }
        let _e211 = phi_2487_;
        if _e211 {
            let _e212 = mu_7;
            param_124 = _e212;
            let _e213 = alpha_11;
            param_125 = _e213;
            let _e215 = (*l_10).eta;
            param_126 = _e215;
            let _e216 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_124), (&param_125), (&param_126));
            e_2 = vec3(_e216);
            let _e218 = e_2;
            let _e220 = (*l_10).c0_;
            let _e222 = (*ms_1);
            return clamp(((_e218 * _e220) * _e222), vec3(0f), vec3(1f));
        }
        let _e227 = mu_7;
        param_127 = _e227;
        let _e228 = alpha_11;
        param_128 = _e228;
        let _e229 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_127), (&param_128));
        ab = _e229;
        let _e230 = (*l_10);
        param_129 = _e230;
        param_130 = 1f;
        param_131 = true;
        let _e231 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_129), (&param_130), (&param_131));
        f0_ = _e231;
        let _e232 = (*l_10);
        param_132 = _e232;
        param_133 = 0f;
        param_134 = true;
        let _e233 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_132), (&param_133), (&param_134));
        f90_ = _e233;
        let _e235 = (*l_10).kind;
        if (_e235 == 1i) {
            let _e238 = (*l_10).c0_;
            local_22 = _e238;
        } else {
            local_22 = vec3<f32>(1f, 1f, 1f);
        }
        let _e239 = local_22;
        tint_1 = _e239;
        let _e241 = (*l_10).alpha;
        param_135 = _e241;
        let _e242 = mxc_is_delta_u0028_vf2_u003b((&param_135));
        if _e242 {
            let _e243 = (*l_10);
            param_136 = _e243;
            let _e244 = mu_7;
            param_137 = _e244;
            param_138 = true;
            let _e245 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_136), (&param_137), (&param_138));
            let _e246 = tint_1;
            return (_e245 * _e246);
        }
        let _e248 = f0_;
        let _e250 = ab[0u];
        let _e252 = f90_;
        let _e254 = ab[1u];
        let _e257 = tint_1;
        let _e259 = (*ms_1);
        return clamp(((((_e248 * _e250) + (_e252 * _e254)) * _e257) * _e259), vec3(0f), vec3(1f));
    }
    let _e265 = (*l_10).kind;
    if (_e265 == 4i) {
        let _e268 = (*l_10).c0_;
        let _e270 = (*l_10).p0_;
        param_139 = _e270;
        let _e271 = mu_7;
        param_140 = _e271;
        let _e272 = mxc_fon_albedo_u0028_f1_u003b_f1_u003b((&param_139), (&param_140));
        return (_e268 * _e272);
    }
    let _e275 = (*l_10).kind;
    if (_e275 == 8i) {
        let _e278 = (*l_10).c0_;
        return _e278;
    }
    let _e280 = (*l_10).c0_;
    return _e280;
}

fn mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_11: ptr<function, MxcLobe>, woLocal: ptr<function, vec3<f32>>, ms_2: ptr<function, vec3<f32>>) -> f32 {
    var param_141: MxcLobe;
    var param_142: vec3<f32>;
    var param_143: vec3<f32>;
    var param_144: vec3<f32>;

    let _e156 = (*l_11).weight;
    if all((_e156 == vec3<f32>(0f, 0f, 0f))) {
        return 0f;
    }
    let _e160 = (*l_11).weight;
    let _e161 = (*l_11);
    param_141 = _e161;
    let _e162 = (*woLocal);
    param_142 = _e162;
    let _e163 = (*ms_2);
    param_143 = _e163;
    let _e164 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_141), (&param_142), (&param_143));
    param_144 = (_e160 * _e164);
    let _e166 = mxc_luminance_u0028_vf3_u003b((&param_144));
    return (max(_e166, 0f) + 0.0001f);
}

fn mxc_walk_texel_u0028_f1_u003b_f1_u003b(column: ptr<function, f32>, row: ptr<function, f32>) -> f32 {
    var t_4: vec2<f32>;

    let _e151 = (*column);
    let _e153 = (*row);
    t_4 = (vec2<f32>((_e151 + 0.5f), (_e153 + 0.5f)) / vec2<f32>(32f, 2070f));
    let _e157 = t_4;
    let _e158 = textureSampleLevel(mxc_tables_texture, mxc_tables_sampler, _e157, 0f);
    return _e158.x;
}

fn mxc_walk_eta_index_u0028_f1_u003b(eta_2: ptr<function, f32>) -> f32 {
    var e_3: f32;

    let _e150 = (*eta_2);
    e_3 = max(_e150, 1f);
    let _e152 = e_3;
    let _e155 = e_3;
    return (clamp(((2f * (_e152 - 1f)) / (_e155 + 1f)), 0f, 1f) * 12f);
}

fn mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b(mu_8: ptr<function, f32>, alpha_12: ptr<function, f32>, eta_3: ptr<function, f32>) -> f32 {
    var fe: f32;
    var param_145: f32;
    var e0_: f32;
    var column_1: f32;
    var row_1: f32;
    var a_5: f32;
    var param_146: f32;
    var param_147: f32;
    var b_3: f32;
    var param_148: f32;
    var param_149: f32;

    let _e162 = (*eta_3);
    param_145 = _e162;
    let _e163 = mxc_walk_eta_index_u0028_f1_u003b((&param_145));
    fe = _e163;
    let _e164 = fe;
    e0_ = min(floor(_e164), 11f);
    let _e167 = (*mu_8);
    column_1 = (sqrt(clamp(_e167, 0f, 1f)) * 31f);
    let _e171 = (*alpha_12);
    row_1 = (1654f + (sqrt(clamp(_e171, 0f, 1f)) * 31f));
    let _e176 = row_1;
    let _e177 = e0_;
    let _e180 = column_1;
    param_146 = _e180;
    param_147 = (_e176 + (_e177 * 32f));
    let _e181 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_146), (&param_147));
    a_5 = _e181;
    let _e182 = row_1;
    let _e183 = e0_;
    let _e187 = column_1;
    param_148 = _e187;
    param_149 = (_e182 + ((_e183 + 1f) * 32f));
    let _e188 = mxc_walk_texel_u0028_f1_u003b_f1_u003b((&param_148), (&param_149));
    b_3 = _e188;
    let _e189 = a_5;
    let _e190 = b_3;
    let _e191 = fe;
    let _e192 = e0_;
    return mix(_e189, _e190, (_e191 - _e192));
}

fn mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b(mu_9: ptr<function, f32>, alpha_13: ptr<function, f32>, eta_4: ptr<function, f32>) -> f32 {
    var param_150: f32;
    var param_151: f32;
    var param_152: f32;
    var param_153: f32;
    var param_154: f32;
    var param_155: f32;

    let _e157 = (*eta_4);
    if (_e157 >= 1f) {
        let _e159 = (*mu_9);
        param_150 = _e159;
        let _e160 = (*alpha_13);
        param_151 = _e160;
        let _e161 = (*eta_4);
        param_152 = _e161;
        let _e162 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_150), (&param_151), (&param_152));
        return _e162.y;
    }
    let _e164 = (*eta_4);
    let _e167 = (*mu_9);
    param_153 = _e167;
    let _e168 = (*alpha_13);
    param_154 = _e168;
    param_155 = (1f / max(_e164, 0.001f));
    let _e169 = mxc_dielectric_table_u0028_f1_u003b_f1_u003b_f1_u003b((&param_153), (&param_154), (&param_155));
    return _e169.z;
}

fn mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_12: ptr<function, MxcLobe>, wo_11: ptr<function, vec3<f32>>) -> bool {
    var phi_2183_: bool;

    let _e151 = (*wo_11)[2u];
    let _e152 = (_e151 <= 0f);
    phi_2183_ = _e152;
    if !(_e152) {
        let _e155 = (*l_12).eta;
        phi_2183_ = (_e155 < 1f);
    }
    let _e158 = phi_2183_;
    if _e158 {
        return false;
    }
    return true;
}

fn mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b(l_13: ptr<function, MxcLobe>) -> bool {
    let _e150 = (*l_13).eta;
    return (abs((_e150 - 1f)) < 0.0001f);
}

fn mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b(l_14: ptr<function, MxcLobe>, wo_12: ptr<function, vec3<f32>>, ms_3: ptr<function, vec3<f32>>) -> f32 {
    var param_156: vec2<f32>;
    var param_157: MxcLobe;
    var param_158: MxcLobe;
    var param_159: vec3<f32>;
    var alpha_14: f32;
    var rss: f32;
    var param_160: f32;
    var param_161: f32;
    var param_162: f32;
    var tss: f32;
    var param_163: f32;
    var param_164: f32;
    var param_165: f32;
    var param_166: f32;
    var param_167: f32;
    var param_168: f32;
    var phi_2216_: bool;
    var phi_2222_: bool;
    var phi_2230_: bool;
    var phi_2238_: bool;

    let _e168 = (*l_14).kind;
    let _e169 = (_e168 != 1i);
    phi_2216_ = _e169;
    if !(_e169) {
        let _e172 = (*l_14).alpha;
        param_156 = _e172;
        let _e173 = mxc_is_delta_u0028_vf2_u003b((&param_156));
        phi_2216_ = _e173;
    }
    let _e175 = phi_2216_;
    phi_2222_ = _e175;
    if !(_e175) {
        let _e177 = (*l_14);
        param_157 = _e177;
        let _e178 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_157));
        phi_2222_ = _e178;
    }
    let _e180 = phi_2222_;
    phi_2230_ = _e180;
    if !(_e180) {
        let _e183 = (*l_14).mode;
        phi_2230_ = ((_e183 & 4i) != 0i);
    }
    let _e187 = phi_2230_;
    phi_2238_ = _e187;
    if !(_e187) {
        let _e189 = (*l_14);
        param_158 = _e189;
        let _e190 = (*wo_12);
        param_159 = _e190;
        let _e191 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_158), (&param_159));
        phi_2238_ = !(_e191);
    }
    let _e194 = phi_2238_;
    if _e194 {
        let _e196 = (*ms_3)[0u];
        return _e196;
    }
    let _e199 = (*l_14).alpha[0u];
    let _e202 = (*l_14).alpha[1u];
    alpha_14 = sqrt((_e199 * _e202));
    let _e206 = (*wo_12)[2u];
    param_160 = _e206;
    let _e207 = alpha_14;
    param_161 = _e207;
    let _e209 = (*l_14).eta;
    param_162 = _e209;
    let _e210 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_160), (&param_161), (&param_162));
    rss = _e210;
    let _e212 = (*wo_12)[2u];
    param_163 = _e212;
    let _e213 = alpha_14;
    param_164 = _e213;
    let _e215 = (*l_14).eta;
    param_165 = _e215;
    let _e216 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_163), (&param_164), (&param_165));
    let _e217 = rss;
    tss = (_e216 - _e217);
    let _e220 = (*wo_12)[2u];
    param_166 = _e220;
    let _e221 = alpha_14;
    param_167 = _e221;
    let _e223 = (*l_14).eta;
    param_168 = _e223;
    let _e224 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_166), (&param_167), (&param_168));
    let _e226 = tss;
    return clamp(((1f - _e224) / max(_e226, 0.05f)), 1f, 20f);
}

fn mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_15: ptr<function, MxcLobe>, wo_13: ptr<function, vec3<f32>>) -> vec3<f32> {
    var microfacet: bool;
    var param_169: vec2<f32>;
    var alpha_15: f32;
    var param_170: MxcLobe;
    var param_171: MxcLobe;
    var param_172: vec3<f32>;
    var rss_1: f32;
    var param_173: f32;
    var param_174: f32;
    var param_175: f32;
    var param_176: f32;
    var param_177: f32;
    var param_178: f32;
    var e_4: f32;
    var param_179: MxcLobe;
    var param_180: bool;
    var param_181: f32;
    var param_182: f32;
    var param_183: f32;
    var k_3: vec3<f32>;
    var ab_1: vec2<f32>;
    var param_184: f32;
    var param_185: f32;
    var e_5: f32;
    var param_186: MxcLobe;
    var param_187: f32;
    var param_188: bool;
    var phi_2314_: bool;
    var phi_2321_: bool;
    var phi_2330_: bool;
    var phi_2346_: bool;
    var phi_2358_: bool;

    let _e178 = (*l_15).kind;
    let _e179 = (_e178 == 1i);
    phi_2314_ = _e179;
    if !(_e179) {
        let _e182 = (*l_15).kind;
        phi_2314_ = (_e182 == 2i);
    }
    let _e185 = phi_2314_;
    phi_2321_ = _e185;
    if !(_e185) {
        let _e188 = (*l_15).kind;
        phi_2321_ = (_e188 == 3i);
    }
    let _e191 = phi_2321_;
    microfacet = _e191;
    let _e192 = microfacet;
    let _e193 = !(_e192);
    phi_2330_ = _e193;
    if !(_e193) {
        let _e196 = (*l_15).alpha;
        param_169 = _e196;
        let _e197 = mxc_is_delta_u0028_vf2_u003b((&param_169));
        phi_2330_ = _e197;
    }
    let _e199 = phi_2330_;
    if _e199 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e202 = (*l_15).alpha[0u];
    let _e205 = (*l_15).alpha[1u];
    alpha_15 = sqrt((_e202 * _e205));
    let _e209 = (*l_15).kind;
    let _e210 = (_e209 == 1i);
    phi_2346_ = _e210;
    if _e210 {
        let _e211 = (*l_15);
        param_170 = _e211;
        let _e212 = mxc_index_matched_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b((&param_170));
        phi_2346_ = _e212;
    }
    let _e214 = phi_2346_;
    if _e214 {
        return vec3<f32>(1f, 1f, 1f);
    }
    let _e216 = (*l_15).kind;
    let _e217 = (_e216 == 1i);
    phi_2358_ = _e217;
    if _e217 {
        let _e219 = (*l_15).mode;
        phi_2358_ = ((_e219 & 4i) == 0i);
    }
    let _e223 = phi_2358_;
    if _e223 {
        let _e224 = (*l_15);
        param_171 = _e224;
        let _e225 = (*wo_13);
        param_172 = _e225;
        let _e226 = mxc_dielectric_walk_split_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_171), (&param_172));
        if _e226 {
            let _e228 = (*wo_13)[2u];
            param_173 = _e228;
            let _e229 = alpha_15;
            param_174 = _e229;
            let _e231 = (*l_15).eta;
            param_175 = _e231;
            let _e232 = mxc_dielectric_albedo_u0028_f1_u003b_f1_u003b_f1_u003b((&param_173), (&param_174), (&param_175));
            rss_1 = _e232;
            let _e234 = (*wo_13)[2u];
            param_176 = _e234;
            let _e235 = alpha_15;
            param_177 = _e235;
            let _e237 = (*l_15).eta;
            param_178 = _e237;
            let _e238 = mxc_walk_reflectance_u0028_f1_u003b_f1_u003b_f1_u003b((&param_176), (&param_177), (&param_178));
            let _e239 = rss_1;
            return vec3(clamp((_e238 / max(_e239, 0.0001f)), 1f, 20f));
        }
        let _e245 = (*wo_13)[2u];
        let _e248 = (*wo_13)[2u];
        let _e250 = (*l_15);
        param_179 = _e250;
        param_180 = (_e248 >= 0f);
        let _e251 = mxc_lobe_eta_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_b1_u003b((&param_179), (&param_180));
        param_181 = abs(_e245);
        let _e252 = alpha_15;
        param_182 = _e252;
        param_183 = _e251;
        let _e253 = mxc_dielectric_albedo_rt_u0028_f1_u003b_f1_u003b_f1_u003b((&param_181), (&param_182), (&param_183));
        e_4 = _e253;
        let _e254 = e_4;
        k_3 = vec3((1f / max(_e254, 0.05f)));
        let _e258 = k_3;
        return _e258;
    }
    let _e260 = (*wo_13)[2u];
    param_184 = max(_e260, 0f);
    let _e262 = alpha_15;
    param_185 = _e262;
    let _e263 = mxc_split_sum_u0028_f1_u003b_f1_u003b((&param_184), (&param_185));
    ab_1 = _e263;
    let _e265 = ab_1[0u];
    let _e267 = ab_1[1u];
    e_5 = (_e265 + _e267);
    let _e269 = (*l_15);
    param_186 = _e269;
    param_187 = 1f;
    param_188 = true;
    let _e270 = mxc_lobe_fresnel_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_f1_u003b_b1_u003b((&param_186), (&param_187), (&param_188));
    let _e271 = e_5;
    let _e274 = e_5;
    return (vec3(1f) + ((_e270 * (1f - _e271)) / vec3(max(_e274, 0.05f))));
}

fn mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b(c_8: ptr<function, MxcClosure>, wo_14: ptr<function, vec3<f32>>) {
    var k_4: i32;
    var l_16: MxcLobe;
    var o_4: vec3<f32>;
    var param_189: vec3<f32>;
    var param_190: vec3<f32>;
    var param_191: mat3x3<f32>;
    var param_192: vec3<f32>;
    var param_193: MxcLobe;
    var param_194: vec3<f32>;
    var param_195: MxcLobe;
    var param_196: vec3<f32>;
    var param_197: vec3<f32>;
    var param_198: MxcLobe;
    var param_199: vec3<f32>;
    var param_200: vec3<f32>;

    (*c_8).choiceTotal = 0f;
    k_4 = 0i;
    loop {
        let _e166 = k_4;
        let _e168 = (*c_8).count;
        if (_e166 < _e168) {
            let _e170 = k_4;
            let _e173 = (*c_8).lobes[_e170];
            l_16 = _e173;
            let _e174 = k_4;
            (*c_8).ms[_e174] = vec3<f32>(1f, 1f, 1f);
            let _e177 = k_4;
            (*c_8).msT[_e177] = 1f;
            let _e180 = k_4;
            (*c_8).choice[_e180] = 0f;
            let _e184 = l_16.weight;
            if all((_e184 == vec3<f32>(0f, 0f, 0f))) {
                continue;
            }
            let _e188 = l_16.N;
            param_189 = _e188;
            let _e190 = l_16.T;
            param_190 = _e190;
            let _e191 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_189), (&param_190));
            param_191 = _e191;
            let _e192 = (*wo_14);
            param_192 = _e192;
            let _e193 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_191), (&param_192));
            o_4 = _e193;
            let _e194 = k_4;
            let _e195 = l_16;
            param_193 = _e195;
            let _e196 = o_4;
            param_194 = _e196;
            let _e197 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_193), (&param_194));
            (*c_8).ms[_e194] = _e197;
            let _e200 = k_4;
            let _e201 = k_4;
            let _e202 = l_16;
            param_195 = _e202;
            let _e203 = o_4;
            param_196 = _e203;
            let _e206 = (*c_8).ms[_e201];
            param_197 = _e206;
            let _e207 = mxc_lobe_ms_transmit_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_195), (&param_196), (&param_197));
            (*c_8).msT[_e200] = _e207;
            let _e210 = k_4;
            let _e211 = k_4;
            let _e212 = l_16;
            param_198 = _e212;
            let _e213 = o_4;
            param_199 = _e213;
            let _e216 = (*c_8).ms[_e211];
            param_200 = _e216;
            let _e217 = mxc_lobe_choice_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_198), (&param_199), (&param_200));
            (*c_8).choice[_e210] = _e217;
            let _e220 = k_4;
            let _e223 = (*c_8).choice[_e220];
            let _e225 = (*c_8).choiceTotal;
            (*c_8).choiceTotal = (_e225 + _e223);
            continue;
        } else {
            break;
        }
        continuing {
            let _e228 = k_4;
            k_4 = (_e228 + 1i);
        }
    }
    return;
}

fn mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_17: ptr<function, MxcLobe>, wo_15: ptr<function, vec3<f32>>) -> vec3<f32> {
    var param_201: MxcLobe;
    var param_202: vec3<f32>;
    var param_203: MxcLobe;
    var param_204: vec3<f32>;
    var param_205: vec3<f32>;

    let _e155 = (*l_17);
    param_201 = _e155;
    let _e156 = (*wo_15);
    param_202 = _e156;
    let _e157 = mxc_lobe_ms_scale_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_201), (&param_202));
    let _e158 = (*l_17);
    param_203 = _e158;
    let _e159 = (*wo_15);
    param_204 = _e159;
    param_205 = _e157;
    let _e160 = mxc_lobe_albedo_scaled_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b_vf3_u003b((&param_203), (&param_204), (&param_205));
    return _e160;
}

fn mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b(l_18: ptr<function, MxcLobe>, wo_16: ptr<function, vec3<f32>>) -> vec3<f32> {
    var white: MxcLobe;
    var param_206: MxcLobe;
    var param_207: vec3<f32>;
    var param_208: MxcLobe;
    var param_209: vec3<f32>;
    var phi_2601_: bool;

    let _e156 = (*l_18).kind;
    let _e157 = (_e156 == 9i);
    phi_2601_ = _e157;
    if !(_e157) {
        let _e160 = (*l_18).kind;
        phi_2601_ = (_e160 == 10i);
    }
    let _e163 = phi_2601_;
    if _e163 {
        let _e164 = (*l_18);
        white = _e164;
        white.c0_ = vec3<f32>(1f, 1f, 1f);
        let _e166 = white;
        param_206 = _e166;
        let _e167 = (*wo_16);
        param_207 = _e167;
        let _e168 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_206), (&param_207));
        return _e168;
    }
    let _e169 = (*l_18);
    param_208 = _e169;
    let _e170 = (*wo_16);
    param_209 = _e170;
    let _e171 = mxc_lobe_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_208), (&param_209));
    return _e171;
}

fn mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b(v_6: ptr<function, vec3<f32>>, fallback: ptr<function, vec3<f32>>) -> vec3<f32> {
    var l2_1: f32;
    var local_23: vec3<f32>;

    let _e152 = (*v_6);
    let _e153 = (*v_6);
    l2_1 = dot(_e152, _e153);
    let _e155 = l2_1;
    if (_e155 > 0.00000000000000000001f) {
        let _e157 = (*v_6);
        let _e158 = l2_1;
        local_23 = (_e157 * inverseSqrt(_e158));
    } else {
        let _e161 = (*fallback);
        local_23 = _e161;
    }
    let _e162 = local_23;
    return _e162;
}

fn mxc_normalmap_u0028_vf3_u003b_vf2_u003b_vf3_u003b_vf3_u003b_vf3_u003b(sampleValue: ptr<function, vec3<f32>>, scale: ptr<function, vec2<f32>>, N_1: ptr<function, vec3<f32>>, T_1: ptr<function, vec3<f32>>, B: ptr<function, vec3<f32>>) -> vec3<f32> {
    var v_7: vec3<f32>;
    var param_210: vec3<f32>;
    var param_211: vec3<f32>;

    let _e156 = (*sampleValue);
    v_7 = ((_e156 * 2f) - vec3(1f));
    let _e160 = (*scale);
    let _e161 = v_7;
    let _e163 = (_e161.xy * _e160);
    v_7[0u] = _e163.x;
    v_7[1u] = _e163.y;
    let _e168 = (*T_1);
    let _e170 = v_7[0u];
    let _e172 = (*B);
    let _e174 = v_7[1u];
    let _e177 = (*N_1);
    let _e179 = v_7[2u];
    param_210 = (((_e168 * _e170) + (_e172 * _e174)) + (_e177 * _e179));
    let _e182 = (*N_1);
    param_211 = _e182;
    let _e183 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_210), (&param_211));
    return _e183;
}

fn mxc_hsv_to_rgb_u0028_vf3_u003b(hsv: ptr<function, vec3<f32>>) -> vec3<f32> {
    var k_5: vec3<f32>;

    let _e151 = (*hsv)[0u];
    k_5 = clamp((abs(((fract((vec3(_e151) + vec3<f32>(0f, 0.6666667f, 0.33333334f))) * 6f) - vec3(3f))) - vec3(1f)), vec3(0f), vec3(1f));
    let _e165 = (*hsv)[2u];
    let _e166 = k_5;
    let _e168 = (*hsv)[1u];
    return (mix(vec3<f32>(1f, 1f, 1f), _e166, vec3(_e168)) * _e165);
}

fn mxc_address_u0028_f1_u003b_i1_u003b(x_6: ptr<function, f32>, mode: ptr<function, i32>) -> bool {
    let _e150 = (*mode);
    if (_e150 == 0i) {
        let _e152 = (*x_6);
        let _e154 = (*x_6);
        return ((_e152 >= 0f) && (_e154 <= 1f));
    }
    let _e157 = (*mode);
    if (_e157 == 1i) {
        let _e159 = (*x_6);
        (*x_6) = clamp(_e159, 0f, 1f);
    } else {
        let _e161 = (*mode);
        if (_e161 == 2i) {
            let _e163 = (*x_6);
            (*x_6) = fract(_e163);
        } else {
            let _e165 = (*x_6);
            (*x_6) = (1f - abs(((_e165 - (floor((_e165 / 2f)) * 2f)) - 1f)));
        }
    }
    return true;
}

fn mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(image_texture: texture_2d<f32>, image_sampler: sampler, uv_1: ptr<function, vec2<f32>>, fallback_1: ptr<function, vec4<f32>>, uaddress: ptr<function, i32>, vaddress: ptr<function, i32>, filtertype: ptr<function, i32>, missing: ptr<function, bool>) -> vec4<f32> {
    var dx: vec2<f32>;
    var dy: vec2<f32>;
    var st: vec2<f32>;
    var param_212: f32;
    var param_213: i32;
    var param_214: f32;
    var param_215: i32;
    var size_2: vec2<f32>;
    var phi_1673_: bool;

    let _e164 = (*uv_1);
    let _e165 = dpdx(_e164);
    let _e166 = mxc_texture_footprint;
    let _e167 = mxc_texture_footprint;
    dx = (_e165 * vec2<f32>(_e166, -(_e167)));
    let _e171 = (*uv_1);
    let _e172 = dpdy(_e171);
    let _e173 = mxc_texture_footprint;
    let _e174 = mxc_texture_footprint;
    dy = (_e172 * vec2<f32>(_e173, -(_e174)));
    let _e178 = (*uv_1);
    st = _e178;
    let _e179 = (*missing);
    if _e179 {
        let _e180 = (*fallback_1);
        return _e180;
    }
    let _e182 = st[0u];
    param_212 = _e182;
    let _e183 = (*uaddress);
    param_213 = _e183;
    let _e184 = mxc_address_u0028_f1_u003b_i1_u003b((&param_212), (&param_213));
    let _e185 = param_212;
    st[0u] = _e185;
    let _e187 = !(_e184);
    phi_1673_ = _e187;
    if !(_e187) {
        let _e190 = st[1u];
        param_214 = _e190;
        let _e191 = (*vaddress);
        param_215 = _e191;
        let _e192 = mxc_address_u0028_f1_u003b_i1_u003b((&param_214), (&param_215));
        let _e193 = param_214;
        st[1u] = _e193;
        phi_1673_ = !(_e192);
    }
    let _e197 = phi_1673_;
    if _e197 {
        let _e198 = (*fallback_1);
        return _e198;
    }
    let _e200 = st[1u];
    st[1u] = (1f - _e200);
    let _e203 = (*filtertype);
    if (_e203 == 1i) {
        let _e205 = textureDimensions(image_texture, 0i);
        size_2 = vec2<f32>(vec2<i32>(_e205));
        let _e208 = st;
        let _e209 = size_2;
        let _e212 = size_2;
        let _e218 = size_2;
        let _e220 = textureSampleLevel(image_texture, image_sampler, ((min(floor((_e208 * _e209)), (_e212 - vec2(1f))) + vec2(0.5f)) / _e218), 0f);
        return _e220;
    }
    let _e221 = st;
    let _e222 = dx;
    let _e223 = dy;
    let _e224 = textureSampleGrad(image_texture, image_sampler, _e221, _e222, _e223);
    return _e224;
}

fn mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b(g_1: ptr<function, MxcGeometry>, wo_17: ptr<function, vec3<f32>>, c_9: ptr<function, MxcClosure>) {
    var v3_: vec2<f32>;
    var v4_: vec2<f32>;
    var v8_: f32;
    var param_216: vec2<f32>;
    var param_217: vec4<f32>;
    var param_218: i32;
    var param_219: i32;
    var param_220: i32;
    var param_221: bool;
    var v10_: f32;
    var v11_: f32;
    var v13_: f32;
    var param_222: vec2<f32>;
    var param_223: vec4<f32>;
    var param_224: i32;
    var param_225: i32;
    var param_226: i32;
    var param_227: bool;
    var v14_: f32;
    var v20_: f32;
    var param_228: vec2<f32>;
    var param_229: vec4<f32>;
    var param_230: i32;
    var param_231: i32;
    var param_232: i32;
    var param_233: bool;
    var v21_: f32;
    var v25_: f32;
    var param_234: vec2<f32>;
    var param_235: vec4<f32>;
    var param_236: i32;
    var param_237: i32;
    var param_238: i32;
    var param_239: bool;
    var v26_: f32;
    var v28_: f32;
    var param_240: vec2<f32>;
    var param_241: vec4<f32>;
    var param_242: i32;
    var param_243: i32;
    var param_244: i32;
    var param_245: bool;
    var v29_: f32;
    var v31_: f32;
    var v32_: f32;
    var v34_: f32;
    var v35_: f32;
    var v36_: vec3<f32>;
    var v38_: vec3<f32>;
    var v39_: vec3<f32>;
    var param_246: vec3<f32>;
    var v40_: vec3<f32>;
    var v41_: vec3<f32>;
    var v43_: vec3<f32>;
    var v44_: vec3<f32>;
    var v45_: vec3<f32>;
    var v46_: vec3<f32>;
    var v48_: vec3<f32>;
    var param_247: vec2<f32>;
    var param_248: vec4<f32>;
    var param_249: i32;
    var param_250: i32;
    var param_251: i32;
    var param_252: bool;
    var v49_: vec3<f32>;
    var v50_: vec3<f32>;
    var v51_: vec3<f32>;
    var v52_: vec3<f32>;
    var param_253: vec3<f32>;
    var param_254: vec2<f32>;
    var param_255: vec3<f32>;
    var param_256: vec3<f32>;
    var param_257: vec3<f32>;
    var v55_: f32;
    var v56_: f32;
    var v57_: vec2<f32>;
    var lobe0_: MxcLobe;
    var param_258: vec3<f32>;
    var param_259: vec3<f32>;
    var e1_: vec3<f32>;
    var param_260: vec3<f32>;
    var param_261: vec3<f32>;
    var param_262: mat3x3<f32>;
    var param_263: vec3<f32>;
    var param_264: MxcLobe;
    var param_265: vec3<f32>;
    var w2_: vec3<f32>;
    var lobe3_: MxcLobe;
    var param_266: vec3<f32>;
    var param_267: vec3<f32>;
    var param_268: MxcClosure;
    var param_269: vec3<f32>;

    let _e244 = (*g_1).uv;
    v3_ = _e244;
    let _e245 = v3_;
    v4_ = (_e245 * vec2<f32>(3f, 3f));
    let _e248 = mxc_params.missing_textures;
    let _e251 = v4_;
    param_216 = _e251;
    param_217 = vec4<f32>(0f, 0f, 0f, 0f);
    param_218 = 2i;
    param_219 = 2i;
    param_220 = 0i;
    param_221 = ((_e248 & 1u) != 0u);
    let _e252 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_0_texture, mxc_texture_0_sampler, (&param_216), (&param_217), (&param_218), (&param_219), (&param_220), (&param_221));
    v8_ = _e252.x;
    let _e254 = v8_;
    v10_ = max(_e254, 0.00001f);
    let _e256 = v10_;
    v11_ = (0.853f / _e256);
    let _e259 = mxc_params.missing_textures;
    let _e262 = v4_;
    param_222 = _e262;
    param_223 = vec4<f32>(0f, 0f, 0f, 0f);
    param_224 = 2i;
    param_225 = 2i;
    param_226 = 0i;
    param_227 = ((_e259 & 2u) != 0u);
    let _e263 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_1_texture, mxc_texture_1_sampler, (&param_222), (&param_223), (&param_224), (&param_225), (&param_226), (&param_227));
    v13_ = _e263.x;
    let _e265 = v11_;
    let _e266 = v13_;
    v14_ = (_e265 * _e266);
    let _e269 = mxc_params.missing_textures;
    let _e272 = v4_;
    param_228 = _e272;
    param_229 = vec4<f32>(0f, 0f, 0f, 0f);
    param_230 = 2i;
    param_231 = 2i;
    param_232 = 0i;
    param_233 = ((_e269 & 4u) != 0u);
    let _e273 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_2_texture, mxc_texture_2_sampler, (&param_228), (&param_229), (&param_230), (&param_231), (&param_232), (&param_233));
    v20_ = _e273.x;
    let _e275 = v20_;
    v21_ = (0.248f * _e275);
    let _e278 = mxc_params.missing_textures;
    let _e281 = v4_;
    param_234 = _e281;
    param_235 = vec4<f32>(0f, 0f, 0f, 0f);
    param_236 = 2i;
    param_237 = 2i;
    param_238 = 0i;
    param_239 = ((_e278 & 8u) != 0u);
    let _e282 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_3_texture, mxc_texture_3_sampler, (&param_234), (&param_235), (&param_236), (&param_237), (&param_238), (&param_239));
    v25_ = _e282.x;
    let _e284 = v25_;
    v26_ = (0.083f * _e284);
    let _e287 = mxc_params.missing_textures;
    let _e290 = v4_;
    param_240 = _e290;
    param_241 = vec4<f32>(0f, 0f, 0f, 0f);
    param_242 = 2i;
    param_243 = 2i;
    param_244 = 0i;
    param_245 = ((_e287 & 16u) != 0u);
    let _e291 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_4_texture, mxc_texture_4_sampler, (&param_240), (&param_241), (&param_242), (&param_243), (&param_244), (&param_245));
    v28_ = _e291.x;
    let _e293 = v26_;
    let _e294 = v28_;
    v29_ = (_e293 + _e294);
    let _e296 = v29_;
    v31_ = (_e296 - 0.35f);
    let _e298 = v31_;
    v32_ = (_e298 * 0.083f);
    let _e300 = v25_;
    v34_ = (0.787f * _e300);
    let _e302 = v29_;
    let _e303 = v34_;
    v35_ = (_e302 * _e303);
    let _e305 = v32_;
    let _e306 = v35_;
    v36_ = vec3<f32>(_e305, 0f, _e306);
    let _e308 = v36_;
    v38_ = (_e308 + vec3<f32>(0.048065394f, 1f, 0.661876f));
    let _e310 = v38_;
    param_246 = _e310;
    let _e311 = mxc_hsv_to_rgb_u0028_vf3_u003b((&param_246));
    v39_ = _e311;
    let _e312 = v39_;
    let _e313 = v21_;
    v40_ = mix(_e312, vec3<f32>(0.56372f, 0.56372f, 0.56372f), vec3(_e313));
    let _e316 = v40_;
    let _e317 = v28_;
    v41_ = (_e316 * _e317);
    let _e319 = v28_;
    v43_ = (vec3<f32>(0.263273f, 0.263273f, 0.263273f) * _e319);
    let _e321 = v43_;
    let _e322 = v41_;
    let _e323 = v8_;
    v44_ = mix(_e321, _e322, vec3(_e323));
    let _e326 = v44_;
    v45_ = clamp(_e326, vec3<f32>(0f, 0f, 0f), vec3<f32>(1f, 1f, 1f));
    let _e328 = v45_;
    v46_ = clamp(_e328, vec3<f32>(0f, 0f, 0f), vec3<f32>(1f, 1f, 1f));
    let _e331 = mxc_params.missing_textures;
    let _e334 = v4_;
    param_247 = _e334;
    param_248 = vec4<f32>(0f, 0f, 0f, 1f);
    param_249 = 2i;
    param_250 = 2i;
    param_251 = 0i;
    param_252 = ((_e331 & 32u) != 0u);
    let _e335 = mxc_sample_image_u0028_t21_u003b_p1_u003b_vf2_u003b_vf4_u003b_i1_u003b_i1_u003b_i1_u003b_b1_u003b(mxc_texture_5_texture, mxc_texture_5_sampler, (&param_247), (&param_248), (&param_249), (&param_250), (&param_251), (&param_252));
    v48_ = _e335.xyz;
    let _e338 = (*g_1).N;
    v49_ = _e338;
    let _e340 = (*g_1).T;
    v50_ = _e340;
    let _e342 = (*g_1).B;
    v51_ = _e342;
    let _e343 = v48_;
    param_253 = _e343;
    param_254 = vec2<f32>(1f, 1f);
    let _e344 = v49_;
    param_255 = _e344;
    let _e345 = v50_;
    param_256 = _e345;
    let _e346 = v51_;
    param_257 = _e346;
    let _e347 = mxc_normalmap_u0028_vf3_u003b_vf2_u003b_vf3_u003b_vf3_u003b_vf3_u003b((&param_253), (&param_254), (&param_255), (&param_256), (&param_257));
    v52_ = _e347;
    let _e348 = v14_;
    let _e349 = v14_;
    v55_ = (_e348 * _e349);
    let _e351 = v55_;
    v56_ = clamp(_e351, 0.0000001f, 1f);
    let _e353 = v56_;
    let _e354 = v56_;
    v57_ = vec2<f32>(_e353, _e354);
    (*c_9).emission = vec3<f32>(0f, 0f, 0f);
    (*c_9).transparency = vec3<f32>(0f, 0f, 0f);
    lobe0_.kind = 1i;
    lobe0_.mode = 1i;
    let _e360 = v52_;
    param_258 = _e360;
    let _e362 = (*g_1).N;
    param_259 = _e362;
    let _e363 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_258), (&param_259));
    lobe0_.N = _e363;
    let _e365 = v50_;
    lobe0_.T = _e365;
    let _e367 = v57_;
    lobe0_.alpha = _e367;
    lobe0_.eta = 1.5f;
    lobe0_.c0_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe0_.p0_ = 0f;
    lobe0_.p1_ = 1f;
    lobe0_.film = vec3<f32>(0f, 0f, 0f);
    lobe0_.tau = vec3<f32>(0f, 0f, 0f);
    lobe0_.tauEta = 1f;
    let _e379 = lobe0_.N;
    param_260 = _e379;
    let _e381 = lobe0_.T;
    param_261 = _e381;
    let _e382 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_260), (&param_261));
    param_262 = _e382;
    let _e383 = (*wo_17);
    param_263 = _e383;
    let _e384 = mxc_to_local_u0028_mf33_u003b_vf3_u003b((&param_262), (&param_263));
    let _e385 = lobe0_;
    param_264 = _e385;
    param_265 = _e384;
    let _e386 = mxc_lobe_layer_albedo_u0028_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u003b_vf3_u003b((&param_264), (&param_265));
    e1_ = _e386;
    let _e387 = e1_;
    w2_ = (vec3<f32>(1f, 1f, 1f) - _e387);
    lobe3_.kind = 4i;
    lobe3_.mode = 1i;
    let _e391 = v52_;
    param_266 = _e391;
    let _e393 = (*g_1).N;
    param_267 = _e393;
    let _e394 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_266), (&param_267));
    lobe3_.N = _e394;
    let _e397 = (*g_1).T;
    lobe3_.T = _e397;
    lobe3_.alpha = vec2<f32>(0f, 0f);
    lobe3_.eta = 1.5f;
    let _e401 = v46_;
    lobe3_.c0_ = _e401;
    lobe3_.c1_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.c2_ = vec3<f32>(1f, 1f, 1f);
    lobe3_.p0_ = 0f;
    lobe3_.p1_ = 1f;
    lobe3_.film = vec3<f32>(0f, 0f, 0f);
    lobe3_.tau = vec3<f32>(0f, 0f, 0f);
    lobe3_.tauEta = 1f;
    lobe0_.weight = vec3<f32>(1f, 1f, 1f);
    let _e411 = lobe0_;
    (*c_9).lobes[0i] = _e411;
    let _e414 = w2_;
    lobe3_.weight = _e414;
    let _e416 = lobe3_;
    (*c_9).lobes[1i] = _e416;
    (*c_9).count = 2i;
    let _e420 = (*c_9);
    param_268 = _e420;
    let _e421 = (*wo_17);
    param_269 = _e421;
    mxc_closure_prepare_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b((&param_268), (&param_269));
    let _e422 = param_268;
    (*c_9) = _e422;
    return;
}

fn mxc_closure_seed_u0028_u1_u003b(seed_1: ptr<function, u32>) {
    return;
}

fn main_1() {
    var g_2: MxcGeometry;
    var N_2: vec3<f32>;
    var param_270: vec3<f32>;
    var param_271: vec3<f32>;
    var wo_18: vec3<f32>;
    var param_272: vec3<f32>;
    var param_273: vec3<f32>;
    var facing: f32;
    var handedness: f32;
    var frame_4: mat3x3<f32>;
    var param_274: vec3<f32>;
    var param_275: vec3<f32>;
    var param_276: vec3<f32>;
    var param_277: vec3<f32>;
    var objectFrame: mat3x3<f32>;
    var param_278: vec3<f32>;
    var param_279: vec3<f32>;
    var param_280: u32;
    var param_281: u32;
    var param_282: u32;
    var param_283: u32;
    var c_10: MxcClosure;
    var param_284: MxcGeometry;
    var param_285: vec3<f32>;
    var param_286: MxcClosure;
    var radiance: vec3<f32>;
    var lights: i32;
    var kinds: i32;
    var image: bool;
    var n_1: i32;
    var local_24: i32;
    var seed_2: u32;
    var param_287: u32;
    var param_288: u32;
    var param_289: u32;
    var pixel: u32;
    var param_290: u32;
    var param_291: u32;
    var shift: vec4<f32>;
    var param_292: u32;
    var param_293: u32;
    var param_294: u32;
    var param_295: u32;
    var sum: vec3<f32>;
    var b_4: i32;
    var batchLights: i32;
    var batchSamples: i32;
    var local_25: i32;
    var index: u32;
    var choice: vec4<f32>;
    var param_296: u32;
    var param_297: u32;
    var param_298: u32;
    var param_299: u32;
    var param_300: u32;
    var param_301: u32;
    var param_302: u32;
    var param_303: u32;
    var smp: MxcSample;
    var param_304: MxcClosure;
    var param_305: vec3<f32>;
    var param_306: vec3<f32>;
    var above_4: bool;
    var seen: vec3<f32>;
    var local_26: vec3<f32>;
    var local_27: vec3<f32>;
    var param_307: vec3<f32>;
    var param_308: vec3<f32>;
    var param_309: vec3<f32>;
    var w_1: f32;
    var local_28: f32;
    var param_310: vec3<f32>;
    var param_311: f32;
    var param_312: vec3<f32>;
    var param_313: f32;
    var param_314: f32;
    var m_5: vec3<f32>;
    var lightPdf: f32;
    var imageWi: vec3<f32>;
    var imageSeen: vec3<f32>;
    var v_8: vec4<f32>;
    var param_315: u32;
    var param_316: u32;
    var param_317: u32;
    var param_318: vec4<f32>;
    var param_319: f32;
    var param_320: vec3<f32>;
    var param_321: f32;
    var param_322: vec3<f32>;
    var j_2: i32;
    var wi_6: vec3<f32>;
    var incoming: vec3<f32>;
    var use_: bool;
    var strategy: i32;
    var local_29: i32;
    var light: vec4<f32>;
    var directional: bool;
    var param_323: vec3<f32>;
    var param_324: vec3<f32>;
    var d_8: vec3<f32>;
    var d2_: f32;
    var spot: vec4<f32>;
    var f_5: vec3<f32>;
    var pdf_2: f32;
    var param_325: MxcClosure;
    var param_326: vec3<f32>;
    var param_327: vec3<f32>;
    var param_328: bool;
    var param_329: f32;
    var w_2: f32;
    var local_30: f32;
    var param_330: vec3<f32>;
    var param_331: f32;
    var param_332: vec3<f32>;
    var param_333: f32;
    var param_334: f32;
    var w_3: f32;
    var param_335: vec3<f32>;
    var param_336: f32;
    var param_337: f32;
    var coverage: f32;
    var param_338: vec3<f32>;
    var phi_663_: bool;
    var phi_674_: bool;
    var phi_736_: bool;
    var phi_793_: bool;
    var phi_794_: bool;
    var phi_827_: bool;
    var phi_869_: bool;

    mxc_texture_footprint = 1f;
    let _e270 = vPosition_1;
    g_2.P = _e270;
    let _e272 = vObjectPosition_1;
    g_2.Pobj = _e272;
    let _e274 = vNormal_1;
    param_270 = _e274;
    param_271 = vec3<f32>(0f, 0f, 1f);
    let _e275 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_270), (&param_271));
    N_2 = _e275;
    let _e276 = gl_FrontFacing_1;
    if !(_e276) {
        let _e278 = N_2;
        N_2 = -(_e278);
    }
    let _e281 = mxc_view.eye;
    let _e283 = vPosition_1;
    param_272 = (_e281.xyz - _e283);
    let _e285 = N_2;
    param_273 = _e285;
    let _e286 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_272), (&param_273));
    wo_18 = _e286;
    let _e287 = wo_18;
    let _e288 = N_2;
    facing = dot(_e287, _e288);
    let _e290 = facing;
    if (_e290 < 0.01f) {
        let _e292 = N_2;
        let _e293 = facing;
        let _e295 = wo_18;
        N_2 = normalize((_e292 + (_e295 * (0.01f - _e293))));
    }
    let _e300 = vTangent_1[3u];
    handedness = select(1f, -1f, (_e300 < 0f));
    let _e303 = N_2;
    param_274 = _e303;
    let _e304 = vTangent_1;
    param_275 = _e304.xyz;
    let _e306 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_274), (&param_275));
    frame_4 = _e306;
    let _e307 = N_2;
    g_2.N = _e307;
    let _e310 = frame_4[0];
    g_2.T = _e310;
    let _e313 = frame_4[1];
    let _e314 = handedness;
    g_2.B = (_e313 * _e314);
    let _e317 = vObjectNormal_1;
    param_276 = _e317;
    param_277 = vec3<f32>(0f, 0f, 1f);
    let _e318 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_276), (&param_277));
    g_2.Nobj = _e318;
    let _e321 = g_2.Nobj;
    param_278 = _e321;
    let _e322 = vObjectTangent_1;
    param_279 = _e322;
    let _e323 = mxc_frame_u0028_vf3_u003b_vf3_u003b((&param_278), (&param_279));
    objectFrame = _e323;
    let _e325 = objectFrame[0];
    g_2.Tobj = _e325;
    let _e328 = objectFrame[1];
    let _e329 = handedness;
    g_2.Bobj = (_e328 * _e329);
    let _e332 = vUv_1;
    g_2.uv = _e332;
    g_2.color = vec4<f32>(1f, 1f, 1f, 1f);
    let _e336 = mxc_view.objectToWorld;
    g_2.objectToWorld = _e336;
    let _e339 = mxc_params.frame;
    g_2.frame = _e339;
    let _e342 = mxc_params.time;
    g_2.time = _e342;
    let _e346 = mxc_view.jitter[2u];
    mxc_texture_footprint = _e346;
    let _e347 = mxc_texture_footprint;
    if !((_e347 > 0f)) {
        mxc_texture_footprint = 1f;
    }
    let _e351 = gl_FragCoord_1[0u];
    let _e354 = gl_FragCoord_1[1u];
    let _e358 = mxc_view.counts[2u];
    param_280 = (bitcast<u32>(_e358) + 7u);
    let _e361 = mxc_pcg_u0028_u1_u003b((&param_280));
    param_281 = (u32(_e354) + _e361);
    let _e363 = mxc_pcg_u0028_u1_u003b((&param_281));
    param_282 = (u32(_e351) ^ _e363);
    let _e365 = mxc_pcg_u0028_u1_u003b((&param_282));
    param_283 = _e365;
    mxc_closure_seed_u0028_u1_u003b((&param_283));
    let _e366 = g_2;
    param_284 = _e366;
    let _e367 = wo_18;
    param_285 = _e367;
    mxc_material_closure_u0028_struct_u002d_MxcGeometry_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_vf4_u002d_mf44_u002d_f1_u002d_f11_u003b_vf3_u003b_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b((&param_284), (&param_285), (&param_286));
    let _e368 = param_286;
    c_10 = _e368;
    let _e370 = c_10.emission;
    let _e373 = mxc_view.environment[1u];
    radiance = (_e370 * _e373);
    let _e375 = mxc_light_count_u0028_();
    lights = _e375;
    let _e376 = mxc_light_kinds_u0028_();
    kinds = _e376;
    let _e377 = mxc_environment_code_u0028_();
    image = (_e377 == 3i);
    let _e379 = mxc_environment_code_u0028_();
    if (_e379 != 0i) {
        let _e383 = mxc_view.counts[3u];
        local_24 = max(_e383, 1i);
    } else {
        local_24 = 0i;
    }
    let _e385 = local_24;
    n_1 = _e385;
    let _e387 = gl_FragCoord_1[0u];
    let _e390 = gl_FragCoord_1[1u];
    let _e394 = mxc_view.counts[2u];
    param_287 = bitcast<u32>(_e394);
    let _e396 = mxc_pcg_u0028_u1_u003b((&param_287));
    param_288 = (u32(_e390) + _e396);
    let _e398 = mxc_pcg_u0028_u1_u003b((&param_288));
    param_289 = (u32(_e387) + _e398);
    let _e400 = mxc_pcg_u0028_u1_u003b((&param_289));
    seed_2 = _e400;
    let _e402 = gl_FragCoord_1[0u];
    let _e405 = gl_FragCoord_1[1u];
    param_290 = (u32(_e405) + 2654435769u);
    let _e408 = mxc_pcg_u0028_u1_u003b((&param_290));
    param_291 = (u32(_e402) ^ _e408);
    let _e410 = mxc_pcg_u0028_u1_u003b((&param_291));
    pixel = _e410;
    let _e411 = pixel;
    param_292 = _e411;
    let _e412 = mxc_uniform_u0028_u1_u003b((&param_292));
    let _e413 = param_292;
    pixel = _e413;
    let _e414 = pixel;
    param_293 = _e414;
    let _e415 = mxc_uniform_u0028_u1_u003b((&param_293));
    let _e416 = param_293;
    pixel = _e416;
    let _e417 = pixel;
    param_294 = _e417;
    let _e418 = mxc_uniform_u0028_u1_u003b((&param_294));
    let _e419 = param_294;
    pixel = _e419;
    let _e420 = pixel;
    param_295 = _e420;
    let _e421 = mxc_uniform_u0028_u1_u003b((&param_295));
    let _e422 = param_295;
    pixel = _e422;
    shift = vec4<f32>(_e412, _e415, _e418, _e421);
    sum = vec3<f32>(0f, 0f, 0f);
    b_4 = 0i;
    loop {
        let _e424 = b_4;
        let _e425 = n_1;
        let _e426 = lights;
        if (_e424 < max(_e425, select(0i, 1i, (_e426 > 0i)))) {
            let _e431 = b_4;
            let _e433 = lights;
            batchLights = select(0i, _e433, (_e431 == 0i));
            let _e435 = b_4;
            let _e436 = n_1;
            if (_e435 < _e436) {
                let _e438 = image;
                local_25 = (1i + select(0i, 1i, _e438));
            } else {
                local_25 = 0i;
            }
            let _e441 = local_25;
            batchSamples = _e441;
            let _e444 = mxc_view.counts[2u];
            let _e446 = n_1;
            let _e450 = b_4;
            index = ((bitcast<u32>(_e444) * bitcast<u32>(max(_e446, 1i))) + bitcast<u32>(_e450));
            let _e453 = index;
            param_296 = _e453;
            param_297 = 2u;
            let _e454 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_296), (&param_297));
            let _e455 = index;
            param_298 = _e455;
            param_299 = 3u;
            let _e456 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_298), (&param_299));
            let _e457 = index;
            param_300 = _e457;
            param_301 = 5u;
            let _e458 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_300), (&param_301));
            let _e459 = index;
            param_302 = _e459;
            param_303 = 7u;
            let _e460 = mxc_radical_inverse_u0028_u1_u003b_u1_u003b((&param_302), (&param_303));
            let _e462 = shift;
            choice = fract((vec4<f32>(_e454, _e456, _e458, _e460) + _e462));
            smp.valid = false;
            smp.evaluate = false;
            smp.delta = false;
            smp.pdf = 0f;
            smp.weight = vec3<f32>(0f, 0f, 0f);
            let _e470 = N_2;
            smp.wi = _e470;
            let _e472 = n_1;
            if (_e472 > 0i) {
                let _e475 = choice[2u];
                let _e477 = choice[3u];
                let _e479 = choice[0u];
                let _e481 = c_10;
                param_304 = _e481;
                let _e482 = wo_18;
                param_305 = _e482;
                param_306 = vec3<f32>(_e475, _e477, _e479);
                let _e483 = mxc_closure_sample_direction_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b((&param_304), (&param_305), (&param_306));
                smp = _e483;
            }
            let _e485 = smp.wi;
            let _e486 = N_2;
            above_4 = (dot(_e485, _e486) > 0f);
            let _e490 = smp.valid;
            if _e490 {
                let _e491 = above_4;
                if _e491 {
                    let _e493 = smp.wi;
                    local_27 = _e493;
                } else {
                    let _e494 = wo_18;
                    param_307 = -(_e494);
                    let _e497 = smp.wi;
                    param_308 = _e497;
                    let _e498 = mxc_exit_direction_u0028_vf3_u003b_vf3_u003b((&param_307), (&param_308));
                    local_27 = _e498;
                }
                let _e499 = local_27;
                param_309 = _e499;
                let _e500 = mxc_environment_u0028_vf3_u003b((&param_309));
                local_26 = _e500;
            } else {
                local_26 = vec3<f32>(0f, 0f, 0f);
            }
            let _e501 = local_26;
            seen = _e501;
            let _e502 = b_4;
            let _e503 = n_1;
            let _e506 = smp.valid;
            let _e507 = ((_e502 < _e503) && _e506);
            phi_663_ = _e507;
            if _e507 {
                let _e509 = smp.evaluate;
                phi_663_ = !(_e509);
            }
            let _e512 = phi_663_;
            if _e512 {
                let _e513 = image;
                let _e514 = above_4;
                let _e515 = (_e513 && _e514);
                phi_674_ = _e515;
                if _e515 {
                    let _e517 = smp.delta;
                    phi_674_ = !(_e517);
                }
                let _e520 = phi_674_;
                if _e520 {
                    let _e522 = smp.wi;
                    param_310 = _e522;
                    let _e525 = mxc_view.environment[2u];
                    param_311 = _e525;
                    let _e526 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_310), (&param_311));
                    param_312 = _e526;
                    let _e527 = mxc_env_pdf_u0028_vf3_u003b((&param_312));
                    let _e529 = smp.pdf;
                    param_313 = _e529;
                    param_314 = _e527;
                    let _e530 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_313), (&param_314));
                    local_28 = _e530;
                } else {
                    local_28 = 1f;
                }
                let _e531 = local_28;
                w_1 = _e531;
                let _e532 = w_1;
                let _e534 = smp.weight;
                let _e536 = seen;
                let _e538 = sum;
                sum = (_e538 + ((_e534 * _e532) * _e536));
            }
            m_5 = vec3<f32>(0f, 0f, 0f);
            lightPdf = 0f;
            let _e540 = N_2;
            imageWi = _e540;
            imageSeen = vec3<f32>(0f, 0f, 0f);
            let _e541 = image;
            let _e542 = b_4;
            let _e543 = n_1;
            if (_e541 && (_e542 < _e543)) {
                let _e547 = choice[1u];
                let _e548 = seed_2;
                param_315 = _e548;
                let _e549 = mxc_uniform_u0028_u1_u003b((&param_315));
                let _e550 = param_315;
                seed_2 = _e550;
                let _e551 = seed_2;
                param_316 = _e551;
                let _e552 = mxc_uniform_u0028_u1_u003b((&param_316));
                let _e553 = param_316;
                seed_2 = _e553;
                let _e554 = seed_2;
                param_317 = _e554;
                let _e555 = mxc_uniform_u0028_u1_u003b((&param_317));
                let _e556 = param_317;
                seed_2 = _e556;
                v_8 = vec4<f32>(_e547, _e549, _e552, _e555);
                let _e558 = v_8;
                param_318 = _e558;
                let _e559 = mxc_env_sample_u0028_vf4_u003b_f1_u003b((&param_318), (&param_319));
                let _e560 = param_319;
                lightPdf = _e560;
                m_5 = _e559;
                let _e561 = m_5;
                param_320 = _e561;
                let _e564 = mxc_view.environment[2u];
                param_321 = _e564;
                let _e565 = mxc_env_to_world_u0028_vf3_u003b_f1_u003b((&param_320), (&param_321));
                imageWi = _e565;
                let _e566 = lightPdf;
                let _e567 = (_e566 > 0f);
                phi_736_ = _e567;
                if _e567 {
                    let _e568 = imageWi;
                    let _e569 = N_2;
                    phi_736_ = (dot(_e568, _e569) > 0f);
                }
                let _e573 = phi_736_;
                if _e573 {
                    let _e574 = imageWi;
                    param_322 = _e574;
                    let _e575 = mxc_environment_u0028_vf3_u003b((&param_322));
                    imageSeen = _e575;
                }
            }
            j_2 = 0i;
            loop {
                let _e576 = j_2;
                let _e577 = batchLights;
                let _e578 = batchSamples;
                if (_e576 < (_e577 + _e578)) {
                    let _e581 = N_2;
                    wi_6 = _e581;
                    incoming = vec3<f32>(0f, 0f, 0f);
                    use_ = true;
                    let _e582 = n_1;
                    let _e584 = j_2;
                    let _e585 = batchLights;
                    if ((_e582 == 0i) || (_e584 < _e585)) {
                        local_29 = 0i;
                    } else {
                        let _e588 = j_2;
                        let _e589 = batchLights;
                        local_29 = select(2i, 1i, (_e588 == ((_e589 + 1i) - 1i)));
                    }
                    let _e594 = local_29;
                    strategy = _e594;
                    let _e595 = strategy;
                    if (_e595 == 0i) {
                        let _e597 = j_2;
                        let _e600 = mxc_view.lightVector[_e597];
                        light = _e600;
                        let _e601 = j_2;
                        let _e604 = mxc_view.lightRadiance[_e601];
                        incoming = _e604.xyz;
                        let _e606 = kinds;
                        let _e607 = (_e606 == 1i);
                        phi_794_ = _e607;
                        if !(_e607) {
                            let _e609 = kinds;
                            let _e611 = ((_e609 & 1i) != 0i);
                            phi_793_ = _e611;
                            if _e611 {
                                let _e613 = light[3u];
                                phi_793_ = (_e613 == 0f);
                            }
                            let _e616 = phi_793_;
                            phi_794_ = _e616;
                        }
                        let _e618 = phi_794_;
                        directional = _e618;
                        let _e619 = directional;
                        if _e619 {
                            let _e620 = light;
                            param_323 = _e620.xyz;
                            let _e622 = N_2;
                            param_324 = _e622;
                            let _e623 = mxc_safe_normalize_u0028_vf3_u003b_vf3_u003b((&param_323), (&param_324));
                            wi_6 = _e623;
                        } else {
                            let _e624 = light;
                            let _e626 = vPosition_1;
                            d_8 = (_e624.xyz - _e626);
                            let _e628 = d_8;
                            let _e629 = d_8;
                            d2_ = max(dot(_e628, _e629), 0.00000001f);
                            let _e632 = d_8;
                            let _e633 = d2_;
                            wi_6 = (_e632 * inverseSqrt(_e633));
                            let _e636 = d2_;
                            let _e637 = incoming;
                            incoming = (_e637 / vec3(_e636));
                            let _e640 = kinds;
                            let _e642 = ((_e640 & 4i) != 0i);
                            phi_827_ = _e642;
                            if _e642 {
                                let _e644 = light[3u];
                                phi_827_ = (_e644 == 2f);
                            }
                            let _e647 = phi_827_;
                            if _e647 {
                                let _e648 = j_2;
                                let _e651 = mxc_view.lightSpot[_e648];
                                spot = _e651;
                                let _e653 = spot[3u];
                                let _e654 = j_2;
                                let _e658 = mxc_view.lightRadiance[_e654][3u];
                                let _e659 = wi_6;
                                let _e661 = spot;
                                let _e665 = incoming;
                                incoming = (_e665 * smoothstep(_e653, _e658, dot(-(_e659), _e661.xyz)));
                            }
                        }
                    } else {
                        let _e667 = strategy;
                        if (_e667 == 1i) {
                            let _e670 = smp.wi;
                            wi_6 = _e670;
                            let _e671 = seen;
                            incoming = _e671;
                            let _e673 = smp.valid;
                            let _e675 = smp.evaluate;
                            use_ = (_e673 && _e675);
                        } else {
                            let _e677 = imageWi;
                            wi_6 = _e677;
                            let _e678 = imageSeen;
                            incoming = _e678;
                            let _e679 = lightPdf;
                            let _e680 = (_e679 > 0f);
                            phi_869_ = _e680;
                            if _e680 {
                                let _e681 = imageWi;
                                let _e682 = N_2;
                                phi_869_ = (dot(_e681, _e682) > 0f);
                            }
                            let _e686 = phi_869_;
                            use_ = _e686;
                        }
                    }
                    let _e687 = strategy;
                    let _e689 = c_10;
                    param_325 = _e689;
                    let _e690 = wo_18;
                    param_326 = _e690;
                    let _e691 = wi_6;
                    param_327 = _e691;
                    param_328 = (_e687 != 0i);
                    let _e692 = mxc_closure_eval_pdf_u0028_struct_u002d_MxcClosure_u002d_struct_u002d_MxcLobe_u002d_i1_u002d_i1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_vf2_u002d_f1_u002d_vf3_u002d_vf3_u002d_vf3_u002d_f1_u002d_f1_u002d_vf3_u002d_vf3_u002d_f11_u005b_2_u005d_u002d_i1_u002d_f1_u005b_2_u005d_u002d_f1_u002d_vf3_u005b_2_u005d_u002d_f1_u005b_2_u005d_u002d_vf3_u002d_vf31_u003b_vf3_u003b_vf3_u003b_b1_u003b_f1_u003b((&param_325), (&param_326), (&param_327), (&param_328), (&param_329));
                    let _e693 = param_329;
                    pdf_2 = _e693;
                    f_5 = _e692;
                    let _e694 = strategy;
                    if (_e694 == 0i) {
                        let _e696 = f_5;
                        let _e697 = incoming;
                        let _e699 = radiance;
                        radiance = (_e699 + (_e696 * _e697));
                    } else {
                        let _e701 = strategy;
                        if (_e701 == 1i) {
                            let _e703 = use_;
                            let _e704 = pdf_2;
                            if (_e703 && (_e704 > 0f)) {
                                let _e707 = image;
                                let _e708 = above_4;
                                if (_e707 && _e708) {
                                    let _e710 = wi_6;
                                    param_330 = _e710;
                                    let _e713 = mxc_view.environment[2u];
                                    param_331 = _e713;
                                    let _e714 = mxc_env_to_map_u0028_vf3_u003b_f1_u003b((&param_330), (&param_331));
                                    param_332 = _e714;
                                    let _e715 = mxc_env_pdf_u0028_vf3_u003b((&param_332));
                                    let _e716 = pdf_2;
                                    param_333 = _e716;
                                    param_334 = _e715;
                                    let _e717 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_333), (&param_334));
                                    local_30 = _e717;
                                } else {
                                    local_30 = 1f;
                                }
                                let _e718 = local_30;
                                w_2 = _e718;
                                let _e719 = w_2;
                                let _e720 = f_5;
                                let _e722 = pdf_2;
                                let _e725 = incoming;
                                let _e727 = sum;
                                sum = (_e727 + (((_e720 * _e719) / vec3(_e722)) * _e725));
                            }
                        } else {
                            let _e729 = use_;
                            if _e729 {
                                let _e730 = m_5;
                                param_335 = _e730;
                                let _e731 = mxc_env_pdf_u0028_vf3_u003b((&param_335));
                                param_336 = _e731;
                                let _e732 = pdf_2;
                                param_337 = _e732;
                                let _e733 = mxc_power_heuristic_u0028_f1_u003b_f1_u003b((&param_336), (&param_337));
                                w_3 = _e733;
                                let _e734 = w_3;
                                let _e735 = f_5;
                                let _e737 = incoming;
                                let _e739 = lightPdf;
                                let _e742 = sum;
                                sum = (_e742 + (((_e735 * _e734) * _e737) / vec3(_e739)));
                            }
                        }
                    }
                    continue;
                } else {
                    break;
                }
                continuing {
                    let _e744 = j_2;
                    j_2 = (_e744 + 1i);
                }
            }
            continue;
        } else {
            break;
        }
        continuing {
            let _e746 = b_4;
            b_4 = (_e746 + 1i);
        }
    }
    let _e748 = sum;
    let _e749 = n_1;
    let _e754 = radiance;
    radiance = (_e754 + (_e748 / vec3(f32(max(_e749, 1i)))));
    let _e757 = c_10.transparency;
    param_338 = _e757;
    let _e758 = mxc_luminance_u0028_vf3_u003b((&param_338));
    coverage = (1f - clamp(_e758, 0f, 1f));
    let _e761 = radiance;
    let _e762 = coverage;
    outColor = vec4<f32>(_e761.x, _e761.y, _e761.z, _e762);
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
