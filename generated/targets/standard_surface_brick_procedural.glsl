// ==== corpus/materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx: material M_BrickPattern, placements ====
// mxc_tables {"binding":0}
// MxcView {"binding":0}
// MxcParameters {"binding":0}
// mxc_texture_0 {"binding":1}
// mxc_texture_1 {"binding":2}
// mxc_texture_2 {"binding":3}
// mxc_texture_3 {"binding":4}
// mxc_texture_4 {"binding":5}
// mxc_texture_5 {"binding":6}
// mxc_env_radiance {"binding":7}
// MxcEnvDistribution {"binding":1}
// ==== fragment (main) ====
#version 450

struct MxcGeometry
{
    vec3 P;
    vec3 Pobj;
    vec3 N;
    vec3 Nobj;
    vec3 T;
    vec3 Tobj;
    vec3 B;
    vec3 Bobj;
    vec2 uv;
    vec4 color;
    mat4 objectToWorld;
    float frame;
    float time;
};

struct MxcLobe
{
    int kind;
    int mode;
    vec3 weight;
    vec3 N;
    vec3 T;
    vec2 alpha;
    float eta;
    vec3 c0;
    vec3 c1;
    vec3 c2;
    float p0;
    float p1;
    vec3 film;
    vec3 tau;
    float tauEta;
};

struct MxcClosure
{
    MxcLobe lobes[2];
    int count;
    float choice[2];
    float choiceTotal;
    vec3 ms[2];
    float msT[2];
    vec3 msLobe[2];
    vec3 msLobeT[2];
    float msPick[2];
    float msSplit[2];
    vec3 emission;
    vec3 transparency;
};

struct MxcSample
{
    vec3 wi;
    vec3 weight;
    float pdf;
    bool delta;
    bool evaluate;
    bool valid;
};

struct MxcLobeSample
{
    vec3 wi;
    vec3 value;
    float pdf;
    bool delta;
    bool valid;
};

#ifndef SPIRV_CROSS_CONSTANT_ID_0
#define SPIRV_CROSS_CONSTANT_ID_0 -1
#endif
const int MXC_ENVIRONMENT = SPIRV_CROSS_CONSTANT_ID_0;
const bool _250 = (MXC_ENVIRONMENT != (-1));
#ifndef SPIRV_CROSS_CONSTANT_ID_1
#define SPIRV_CROSS_CONSTANT_ID_1 -1
#endif
const int MXC_LIGHT_COUNT = SPIRV_CROSS_CONSTANT_ID_1;
const bool _252 = (MXC_LIGHT_COUNT != (-1));
#ifndef SPIRV_CROSS_CONSTANT_ID_2
#define SPIRV_CROSS_CONSTANT_ID_2 -1
#endif
const int MXC_LIGHT_KINDS = SPIRV_CROSS_CONSTANT_ID_2;
const bool _254 = (MXC_LIGHT_KINDS != (-1));
const int _255 = _254 ? MXC_LIGHT_KINDS : 7;

layout(binding = 0, std140) uniform MxcView
{
    mat4 objectToWorld;
    mat4 normalToWorld;
    mat4 worldToClip;
    vec4 eye;
    vec4 jitter;
    vec4 lightVector[8];
    vec4 lightSpot[8];
    vec4 lightRadiance[8];
    ivec4 counts;
    vec4 environment;
} mxc_view;

layout(binding = 0, std430) readonly buffer MxcParameters
{
    uint missing_textures;
    float frame;
    float time;
} mxc_params;

layout(binding = 1, std430) readonly buffer MxcEnvDistribution
{
    uvec4 mxc_env_size;
    vec4 mxc_env_cells[];
} _233;

layout(binding = 0) uniform sampler2D mxc_tables;
layout(binding = 1) uniform sampler2D mxc_texture_0;
layout(binding = 2) uniform sampler2D mxc_texture_1;
layout(binding = 3) uniform sampler2D mxc_texture_2;
layout(binding = 4) uniform sampler2D mxc_texture_3;
layout(binding = 5) uniform sampler2D mxc_texture_4;
layout(binding = 6) uniform sampler2D mxc_texture_5;
layout(binding = 7) uniform sampler2D mxc_env_radiance;

layout(location = 0) in vec3 vPosition;
layout(location = 4) in vec3 vObjectPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec4 vTangent;
layout(location = 5) in vec3 vObjectNormal;
layout(location = 6) in vec3 vObjectTangent;
layout(location = 3) in vec2 vUv;
layout(location = 0) out vec4 outColor;
float mxc_texture_footprint;

vec3 mxc_safe_normalize(vec3 v, vec3 fallback)
{
    float l2 = dot(v, v);
    vec3 _991;
    if (l2 > 9.9999996826552253889678874634872e-21)
    {
        _991 = v * inversesqrt(l2);
    }
    else
    {
        _991 = fallback;
    }
    return _991;
}

mat3 mxc_frame(vec3 N, vec3 T)
{
    vec3 t = T - (N * dot(N, T));
    float l2 = dot(t, t);
    if (!(l2 > 9.9999999600419720025001879548654e-13))
    {
        float s = (N.z >= 0.0) ? 1.0 : (-1.0);
        float a = (-1.0) / (s + N.z);
        float b = (N.x * N.y) * a;
        t = vec3(1.0 + (((s * N.x) * N.x) * a), s * b, (-s) * N.x);
    }
    else
    {
        t *= inversesqrt(l2);
    }
    return mat3(vec3(t), vec3(cross(N, t)), vec3(N));
}

uint mxc_pcg(uint v)
{
    uint state = (v * 747796405u) + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

void mxc_closure_seed(uint seed)
{
}

bool mxc_address(inout float x, int mode)
{
    if (mode == 0)
    {
        return (x >= 0.0) && (x <= 1.0);
    }
    if (mode == 1)
    {
        x = clamp(x, 0.0, 1.0);
    }
    else
    {
        if (mode == 2)
        {
            x = fract(x);
        }
        else
        {
            x = 1.0 - abs(mod(x, 2.0) - 1.0);
        }
    }
    return true;
}

vec4 mxc_sample_image(sampler2D image, vec2 uv, vec4 fallback, int uaddress, int vaddress, int filtertype, bool missing)
{
    vec2 dx = dFdx(uv) * vec2(mxc_texture_footprint, -mxc_texture_footprint);
    vec2 dy = dFdy(uv) * vec2(mxc_texture_footprint, -mxc_texture_footprint);
    vec2 st = uv;
    if (missing)
    {
        return fallback;
    }
    float param = st.x;
    int param_1 = uaddress;
    bool _1653 = mxc_address(param, param_1);
    st.x = param;
    bool _1656 = !_1653;
    bool _1667;
    if (!_1656)
    {
        float param_2 = st.y;
        int param_3 = vaddress;
        bool _1663 = mxc_address(param_2, param_3);
        st.y = param_2;
        _1667 = !_1663;
    }
    else
    {
        _1667 = _1656;
    }
    if (_1667)
    {
        return fallback;
    }
    st.y = 1.0 - st.y;
    if (filtertype == 1)
    {
        vec2 size = vec2(textureSize(image, 0));
        return textureLod(image, (min(floor(st * size), size - vec2(1.0)) + vec2(0.5)) / size, 0.0);
    }
    return textureGrad(image, st, dx, dy);
}

vec3 mxc_hsv_to_rgb(vec3 hsv)
{
    vec3 k = clamp(abs((fract(vec3(hsv.x) + vec3(0.0, 0.666666686534881591796875, 0.3333333432674407958984375)) * 6.0) - vec3(3.0)) - vec3(1.0), vec3(0.0), vec3(1.0));
    return mix(vec3(1.0), k, vec3(hsv.y)) * hsv.z;
}

vec3 mxc_normalmap(vec3 sampleValue, vec2 scale, vec3 N, vec3 T, vec3 B)
{
    vec3 v = (sampleValue * 2.0) - vec3(1.0);
    vec3 _1559 = v;
    vec2 _1561 = _1559.xy * scale;
    v.x = _1561.x;
    v.y = _1561.y;
    vec3 param = ((T * v.x) + (B * v.y)) + (N * v.z);
    vec3 param_1 = N;
    return mxc_safe_normalize(param, param_1);
}

vec3 mxc_to_local(mat3 frame, vec3 v)
{
    return vec3(dot(v, frame[0]), dot(v, frame[1]), dot(v, frame[2]));
}

bool mxc_is_delta(vec2 alpha)
{
    return max(alpha.x, alpha.y) < 9.9999997473787516355514526367188e-05;
}

bool mxc_index_matched(MxcLobe l)
{
    return abs(l.eta - 1.0) < 9.9999997473787516355514526367188e-05;
}

bool mxc_dielectric_walk_split(MxcLobe l, vec3 wo)
{
    bool _2160 = wo.z <= 0.0;
    bool _2167;
    if (!_2160)
    {
        _2167 = l.eta < 1.0;
    }
    else
    {
        _2167 = _2160;
    }
    if (_2167)
    {
        return false;
    }
    return true;
}

vec4 mxc_table_at(float mu, float x, float firstRow)
{
    vec2 t = (vec2(sqrt(clamp(mu, 0.0, 1.0)), clamp(x, 0.0, 1.0)) * 31.0) + vec2(0.5);
    return textureLod(mxc_tables, vec2(t.x / 32.0, (firstRow + t.y) / 2070.0), 0.0);
}

vec4 mxc_dielectric_table(float mu, float alpha, float e)
{
    float s = sqrt(clamp(0.5 * (e - 1.0), 0.0, 1.0)) * 31.0;
    float s0 = min(floor(s), 30.0);
    float x = sqrt(max(alpha, 0.0));
    float param = mu;
    float param_1 = x;
    float param_2 = 32.0 * (1.0 + s0);
    vec4 a = mxc_table_at(param, param_1, param_2);
    float param_3 = mu;
    float param_4 = x;
    float param_5 = 32.0 * (2.0 + s0);
    vec4 b = mxc_table_at(param_3, param_4, param_5);
    return mix(a, b, vec4(s - s0));
}

float mxc_dielectric_albedo(float mu, float alpha, float eta)
{
    float _1806;
    if (eta >= 1.0)
    {
        _1806 = eta;
    }
    else
    {
        _1806 = 1.0 / max(eta, 0.001000000047497451305389404296875);
    }
    float e = _1806;
    float param = mu;
    float param_1 = alpha;
    float param_2 = e;
    return mxc_dielectric_table(param, param_1, param_2).x;
}

float mxc_walk_eta_index(float eta)
{
    float e = max(eta, 1.0);
    return clamp((2.0 * (e - 1.0)) / (e + 1.0), 0.0, 1.0) * 12.0;
}

float mxc_walk_texel(float column, float row)
{
    vec2 t = vec2(column + 0.5, row + 0.5) / vec2(32.0, 2070.0);
    return textureLod(mxc_tables, t, 0.0).x;
}

float mxc_walk_reflectance(float mu, float alpha, float eta)
{
    float param = eta;
    float fe = mxc_walk_eta_index(param);
    float e0 = min(floor(fe), 11.0);
    float column = sqrt(clamp(mu, 0.0, 1.0)) * 31.0;
    float row = 1654.0 + (sqrt(clamp(alpha, 0.0, 1.0)) * 31.0);
    float param_1 = column;
    float param_2 = row + (e0 * 32.0);
    float a = mxc_walk_texel(param_1, param_2);
    float param_3 = column;
    float param_4 = row + ((e0 + 1.0) * 32.0);
    float b = mxc_walk_texel(param_3, param_4);
    return mix(a, b, fe - e0);
}

float mxc_lobe_eta(MxcLobe l, bool above)
{
    float _1934;
    if (above)
    {
        _1934 = l.eta;
    }
    else
    {
        _1934 = 1.0 / l.eta;
    }
    return _1934;
}

float mxc_dielectric_albedo_rt(float mu, float alpha, float eta)
{
    if (eta >= 1.0)
    {
        float param = mu;
        float param_1 = alpha;
        float param_2 = eta;
        return mxc_dielectric_table(param, param_1, param_2).y;
    }
    float param_3 = mu;
    float param_4 = alpha;
    float param_5 = 1.0 / max(eta, 0.001000000047497451305389404296875);
    return mxc_dielectric_table(param_3, param_4, param_5).z;
}

vec4 mxc_table(float mu, float x)
{
    float param = mu;
    float param_1 = x;
    float param_2 = 0.0;
    return mxc_table_at(param, param_1, param_2);
}

vec2 mxc_split_sum(float mu, float alpha)
{
    float param = mu;
    float param_1 = sqrt(max(alpha, 0.0));
    return mxc_table(param, param_1).xy;
}

float mxc_fresnel_dielectric(float cosi, float eta)
{
    if (abs(eta - 1.0) < 9.9999999747524270787835121154785e-07)
    {
        return 0.0;
    }
    float sin2t = (1.0 - (cosi * cosi)) / (eta * eta);
    if (sin2t >= 1.0)
    {
        return 1.0;
    }
    float cost = sqrt(1.0 - sin2t);
    float rs = (cosi - (eta * cost)) / (cosi + (eta * cost));
    float rp = ((eta * cosi) - cost) / ((eta * cosi) + cost);
    return 0.5 * ((rs * rs) + (rp * rp));
}

vec3 mxc_lobe_fresnel(MxcLobe l, float _cosh, bool above)
{
    vec3 f = vec3(1.0);
    if (l.kind == 1)
    {
        MxcLobe param = l;
        bool param_1 = above;
        float param_2 = _cosh;
        float param_3 = mxc_lobe_eta(param, param_1);
        f = vec3(mxc_fresnel_dielectric(param_2, param_3));
    }
    return f;
}

vec3 mxc_lobe_ms_scale(MxcLobe l, vec3 wo)
{
    bool _2291 = l.kind == 1;
    bool _2298;
    if (!_2291)
    {
        _2298 = l.kind == 2;
    }
    else
    {
        _2298 = _2291;
    }
    bool _2305;
    if (!_2298)
    {
        _2305 = l.kind == 3;
    }
    else
    {
        _2305 = _2298;
    }
    bool microfacet = _2305;
    bool _2307 = !microfacet;
    bool _2314;
    if (!_2307)
    {
        vec2 param = l.alpha;
        _2314 = mxc_is_delta(param);
    }
    else
    {
        _2314 = _2307;
    }
    if (_2314)
    {
        return vec3(1.0);
    }
    float alpha = sqrt(l.alpha.x * l.alpha.y);
    bool _2325 = l.kind == 1;
    bool _2330;
    if (_2325)
    {
        MxcLobe param_1 = l;
        _2330 = mxc_index_matched(param_1);
    }
    else
    {
        _2330 = _2325;
    }
    if (_2330)
    {
        return vec3(1.0);
    }
    bool _2335 = l.kind == 1;
    bool _2342;
    if (_2335)
    {
        _2342 = (l.mode & 4) == 0;
    }
    else
    {
        _2342 = _2335;
    }
    if (_2342)
    {
        MxcLobe param_2 = l;
        vec3 param_3 = wo;
        if (mxc_dielectric_walk_split(param_2, param_3))
        {
            float param_4 = wo.z;
            float param_5 = alpha;
            float param_6 = l.eta;
            float rss = mxc_dielectric_albedo(param_4, param_5, param_6);
            float param_7 = wo.z;
            float param_8 = alpha;
            float param_9 = l.eta;
            return vec3(clamp(mxc_walk_reflectance(param_7, param_8, param_9) / max(rss, 9.9999997473787516355514526367188e-05), 1.0, 20.0));
        }
        MxcLobe param_10 = l;
        bool param_11 = wo.z >= 0.0;
        float param_12 = abs(wo.z);
        float param_13 = alpha;
        float param_14 = mxc_lobe_eta(param_10, param_11);
        float e = mxc_dielectric_albedo_rt(param_12, param_13, param_14);
        vec3 k = vec3(1.0 / max(e, 0.0500000007450580596923828125));
        return k;
    }
    float param_15 = max(wo.z, 0.0);
    float param_16 = alpha;
    vec2 ab = mxc_split_sum(param_15, param_16);
    float e_1 = ab.x + ab.y;
    MxcLobe param_17 = l;
    float param_18 = 1.0;
    bool param_19 = true;
    return vec3(1.0) + ((mxc_lobe_fresnel(param_17, param_18, param_19) * (1.0 - e_1)) / vec3(max(e_1, 0.0500000007450580596923828125)));
}

float mxc_safe_sqrt(float x)
{
    return sqrt(max(x, 0.0));
}

float mxc_fon_albedo(float sigma, float mu)
{
    float a = 1.0 / (1.0 + (0.2877933979034423828125 * sigma));
    float c = clamp(mu, 0.0, 1.0);
    float param = 1.0 - (c * c);
    float s = mxc_safe_sqrt(param);
    float theta = acos(c);
    float _2100;
    if (c > 9.9999997473787516355514526367188e-05)
    {
        _2100 = (1.0 - ((s * s) * s)) / c;
    }
    else
    {
        _2100 = 1.5 * c;
    }
    float tail = _2100;
    float g = ((s * (theta - (s * c))) + ((0.666666686534881591796875 * s) * tail)) - (0.666666686534881591796875 * s);
    return a + (((sigma * a) * g) * 0.3183098733425140380859375);
}

vec3 mxc_lobe_albedo_scaled(MxcLobe l, vec3 wo, vec3 ms)
{
    float mu = clamp(wo.z, 0.0, 1.0);
    bool _2536 = l.kind == 1;
    bool _2543;
    if (!_2536)
    {
        _2543 = l.kind == 2;
    }
    else
    {
        _2543 = _2536;
    }
    bool _2550;
    if (!_2543)
    {
        _2550 = l.kind == 3;
    }
    else
    {
        _2550 = _2543;
    }
    if (_2550)
    {
        float alpha = sqrt(l.alpha.x * l.alpha.y);
        bool _2561 = l.kind == 1;
        bool _2568;
        if (_2561)
        {
            vec2 param = l.alpha;
            _2568 = !mxc_is_delta(param);
        }
        else
        {
            _2568 = _2561;
        }
        if (_2568)
        {
            float param_1 = mu;
            float param_2 = alpha;
            float param_3 = l.eta;
            vec3 e = vec3(mxc_dielectric_albedo(param_1, param_2, param_3));
            return clamp((e * l.c0) * ms, vec3(0.0), vec3(1.0));
        }
        float param_4 = mu;
        float param_5 = alpha;
        vec2 ab = mxc_split_sum(param_4, param_5);
        MxcLobe param_6 = l;
        float param_7 = 1.0;
        bool param_8 = true;
        vec3 f0 = mxc_lobe_fresnel(param_6, param_7, param_8);
        MxcLobe param_9 = l;
        float param_10 = 0.0;
        bool param_11 = true;
        vec3 f90 = mxc_lobe_fresnel(param_9, param_10, param_11);
        vec3 _2524;
        if (l.kind == 1)
        {
            _2524 = l.c0;
        }
        else
        {
            _2524 = vec3(1.0);
        }
        vec3 tint = _2524;
        vec2 param_12 = l.alpha;
        if (mxc_is_delta(param_12))
        {
            MxcLobe param_13 = l;
            float param_14 = mu;
            bool param_15 = true;
            return mxc_lobe_fresnel(param_13, param_14, param_15) * tint;
        }
        return clamp((((f0 * ab.x) + (f90 * ab.y)) * tint) * ms, vec3(0.0), vec3(1.0));
    }
    if (l.kind == 4)
    {
        float param_16 = l.p0;
        float param_17 = mu;
        return l.c0 * mxc_fon_albedo(param_16, param_17);
    }
    if (l.kind == 8)
    {
        return l.c0;
    }
    return l.c0;
}

vec3 mxc_lobe_albedo(MxcLobe l, vec3 wo)
{
    MxcLobe param = l;
    vec3 param_1 = wo;
    MxcLobe param_2 = l;
    vec3 param_3 = wo;
    vec3 param_4 = mxc_lobe_ms_scale(param, param_1);
    return mxc_lobe_albedo_scaled(param_2, param_3, param_4);
}

vec3 mxc_lobe_layer_albedo(MxcLobe l, vec3 wo)
{
    bool _2675 = l.kind == 9;
    bool _2682;
    if (!_2675)
    {
        _2682 = l.kind == 10;
    }
    else
    {
        _2682 = _2675;
    }
    if (_2682)
    {
        MxcLobe white = l;
        white.c0 = vec3(1.0);
        MxcLobe param = white;
        vec3 param_1 = wo;
        return mxc_lobe_albedo(param, param_1);
    }
    MxcLobe param_2 = l;
    vec3 param_3 = wo;
    return mxc_lobe_albedo(param_2, param_3);
}

float mxc_lobe_ms_transmit(MxcLobe l, vec3 wo, vec3 ms)
{
    bool _2193 = l.kind != 1;
    bool _2200;
    if (!_2193)
    {
        vec2 param = l.alpha;
        _2200 = mxc_is_delta(param);
    }
    else
    {
        _2200 = _2193;
    }
    bool _2206;
    if (!_2200)
    {
        MxcLobe param_1 = l;
        _2206 = mxc_index_matched(param_1);
    }
    else
    {
        _2206 = _2200;
    }
    bool _2214;
    if (!_2206)
    {
        _2214 = (l.mode & 4) != 0;
    }
    else
    {
        _2214 = _2206;
    }
    bool _2222;
    if (!_2214)
    {
        MxcLobe param_2 = l;
        vec3 param_3 = wo;
        _2222 = !mxc_dielectric_walk_split(param_2, param_3);
    }
    else
    {
        _2222 = _2214;
    }
    if (_2222)
    {
        return ms.x;
    }
    float alpha = sqrt(l.alpha.x * l.alpha.y);
    float param_4 = wo.z;
    float param_5 = alpha;
    float param_6 = l.eta;
    float rss = mxc_dielectric_albedo(param_4, param_5, param_6);
    float param_7 = wo.z;
    float param_8 = alpha;
    float param_9 = l.eta;
    float tss = mxc_dielectric_albedo_rt(param_7, param_8, param_9) - rss;
    float param_10 = wo.z;
    float param_11 = alpha;
    float param_12 = l.eta;
    return clamp((1.0 - mxc_walk_reflectance(param_10, param_11, param_12)) / max(tss, 0.0500000007450580596923828125), 1.0, 20.0);
}

float mxc_luminance(vec3 c)
{
    return dot(c, vec3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875));
}

float mxc_lobe_choice(MxcLobe l, vec3 woLocal, vec3 ms)
{
    if (all(equal(l.weight, vec3(0.0))))
    {
        return 0.0;
    }
    MxcLobe param = l;
    vec3 param_1 = woLocal;
    vec3 param_2 = ms;
    vec3 param_3 = l.weight * mxc_lobe_albedo_scaled(param, param_1, param_2);
    return max(mxc_luminance(param_3), 0.0) + 9.9999997473787516355514526367188e-05;
}

bool mxc_lobe_ms_shaped(MxcLobe l, vec3 wo)
{
    bool _2413 = wo.z <= 0.0;
    bool _2420;
    if (!_2413)
    {
        vec2 param = l.alpha;
        _2420 = mxc_is_delta(param);
    }
    else
    {
        _2420 = _2413;
    }
    if (_2420)
    {
        return false;
    }
    if (l.kind == 2)
    {
        return true;
    }
    if (l.kind == 3)
    {
        return (l.mode & 1) != 0;
    }
    bool _2439 = l.kind == 1;
    bool _2446;
    if (_2439)
    {
        _2446 = (l.mode & 1) != 0;
    }
    else
    {
        _2446 = _2439;
    }
    bool _2453;
    if (_2446)
    {
        _2453 = (l.mode & 4) == 0;
    }
    else
    {
        _2453 = _2446;
    }
    bool _2459;
    if (_2453)
    {
        MxcLobe param_1 = l;
        _2459 = !mxc_index_matched(param_1);
    }
    else
    {
        _2459 = _2453;
    }
    bool _2465;
    if (_2459)
    {
        MxcLobe param_2 = l;
        vec3 param_3 = wo;
        _2465 = mxc_dielectric_walk_split(param_2, param_3);
    }
    else
    {
        _2465 = _2459;
    }
    return _2465;
}

bool mxc_lobe_transmits(MxcLobe l)
{
    return false;
}

MxcLobe mxc_ms_lobe(MxcLobe l, bool transmitted)
{
    MxcLobe m = l;
    m.alpha = min(l.alpha * (transmitted ? 3.0 : 1.5), vec2(1.0));
    int _2471;
    if (transmitted)
    {
        _2471 = l.mode & (-2);
    }
    else
    {
        _2471 = l.mode & (-3);
    }
    m.mode = _2471;
    if (l.kind == 1)
    {
        m.c0 = vec3(1.0);
        m.c1 = vec3(1.0);
    }
    return m;
}

void mxc_closure_prepare(inout MxcClosure c, vec3 wo)
{
    c.choiceTotal = 0.0;
    float _3243;
    for (int k = 0; k < c.count; k++)
    {
        MxcLobe l = c.lobes[k];
        c.ms[k] = vec3(1.0);
        c.msT[k] = 1.0;
        c.msLobe[k] = vec3(0.0);
        c.msLobeT[k] = vec3(0.0);
        c.msPick[k] = 0.0;
        c.msSplit[k] = 1.0;
        c.choice[k] = 0.0;
        if (all(equal(l.weight, vec3(0.0))))
        {
            continue;
        }
        vec3 param = l.N;
        vec3 param_1 = l.T;
        mat3 param_2 = mxc_frame(param, param_1);
        vec3 param_3 = wo;
        vec3 o = mxc_to_local(param_2, param_3);
        MxcLobe param_4 = l;
        vec3 param_5 = o;
        vec3 ms = mxc_lobe_ms_scale(param_4, param_5);
        MxcLobe param_6 = l;
        vec3 param_7 = o;
        vec3 param_8 = ms;
        c.msT[k] = mxc_lobe_ms_transmit(param_6, param_7, param_8);
        MxcLobe param_9 = l;
        vec3 param_10 = o;
        vec3 param_11 = ms;
        c.choice[k] = mxc_lobe_choice(param_9, param_10, param_11);
        c.choiceTotal += c.choice[k];
        MxcLobe param_12 = l;
        vec3 param_13 = o;
        if (mxc_lobe_ms_shaped(param_12, param_13))
        {
            float alpha = sqrt(l.alpha.x * l.alpha.y);
            MxcLobe param_14 = l;
            vec3 param_15 = o;
            vec3 param_16 = vec3(1.0);
            vec3 reflected = mxc_lobe_albedo_scaled(param_14, param_15, param_16);
            MxcLobe param_17 = l;
            vec3 param_18 = o;
            vec3 param_19 = ms;
            vec3 addedR = max(mxc_lobe_albedo_scaled(param_17, param_18, param_19) - reflected, vec3(0.0));
            vec3 transmitted = vec3(0.0);
            vec3 addedT = vec3(0.0);
            bool _3331 = l.kind == 1;
            bool _3336;
            if (_3331)
            {
                MxcLobe param_20 = l;
                _3336 = mxc_lobe_transmits(param_20);
            }
            else
            {
                _3336 = _3331;
            }
            if (_3336)
            {
                float param_21 = o.z;
                float param_22 = alpha;
                float param_23 = l.eta;
                float rss = mxc_dielectric_albedo(param_21, param_22, param_23);
                float param_24 = o.z;
                float param_25 = alpha;
                float param_26 = l.eta;
                transmitted = l.c1 * max(mxc_dielectric_albedo_rt(param_24, param_25, param_26) - rss, 0.0);
                addedT = transmitted * max(c.msT[k] - 1.0, 0.0);
            }
            MxcLobe param_27 = l;
            bool param_28 = false;
            MxcLobe mr = mxc_ms_lobe(param_27, param_28);
            MxcLobe param_29 = mr;
            vec3 param_30 = o;
            vec3 param_31 = vec3(1.0);
            vec3 broadR = mxc_lobe_albedo_scaled(param_29, param_30, param_31);
            float broadT = 1.0;
            bool _3371 = l.kind == 1;
            bool _3376;
            if (_3371)
            {
                MxcLobe param_32 = l;
                _3376 = mxc_lobe_transmits(param_32);
            }
            else
            {
                _3376 = _3371;
            }
            if (_3376)
            {
                MxcLobe param_33 = l;
                bool param_34 = true;
                MxcLobe mt = mxc_ms_lobe(param_33, param_34);
                float at = sqrt(mt.alpha.x * mt.alpha.y);
                float param_35 = o.z;
                float param_36 = at;
                float param_37 = l.eta;
                float param_38 = o.z;
                float param_39 = at;
                float param_40 = l.eta;
                broadT = mxc_dielectric_albedo_rt(param_35, param_36, param_37) - mxc_dielectric_albedo(param_38, param_39, param_40);
            }
            c.msLobe[k] = addedR / max(broadR, vec3(9.9999997473787516355514526367188e-05));
            c.msLobeT[k] = addedT / vec3(max(broadT, 9.9999997473787516355514526367188e-05));
            vec3 param_41 = ((reflected + addedR) + transmitted) + addedT;
            float total = max(mxc_luminance(param_41), 9.9999999747524270787835121154785e-07);
            vec3 param_42 = addedR + addedT;
            float added = mxc_luminance(param_42);
            c.msPick[k] = 0.999000012874603271484375 * min(added / total, 1.0);
            if (added > 0.0)
            {
                vec3 param_43 = addedR;
                _3243 = mxc_luminance(param_43) / added;
            }
            else
            {
                _3243 = 1.0;
            }
            c.msSplit[k] = _3243;
            c.msT[k] = 1.0;
        }
        else
        {
            c.ms[k] = ms;
        }
    }
}

void mxc_material_closure(MxcGeometry g, vec3 wo, inout MxcClosure c)
{
    vec2 v3 = g.uv;
    vec2 v4 = v3 * vec2(3.0);
    vec2 param = v4;
    vec4 param_1 = vec4(0.0);
    int param_2 = 2;
    int param_3 = 2;
    int param_4 = 0;
    bool param_5 = (mxc_params.missing_textures & 1u) != 0u;
    float v8 = mxc_sample_image(mxc_texture_0, param, param_1, param_2, param_3, param_4, param_5).x;
    float v10 = max(v8, 9.9999997473787516355514526367188e-06);
    float v11 = 0.852999985218048095703125 / v10;
    vec2 param_6 = v4;
    vec4 param_7 = vec4(0.0);
    int param_8 = 2;
    int param_9 = 2;
    int param_10 = 0;
    bool param_11 = (mxc_params.missing_textures & 2u) != 0u;
    float v13 = mxc_sample_image(mxc_texture_1, param_6, param_7, param_8, param_9, param_10, param_11).x;
    float v14 = v11 * v13;
    vec2 param_12 = v4;
    vec4 param_13 = vec4(0.0);
    int param_14 = 2;
    int param_15 = 2;
    int param_16 = 0;
    bool param_17 = (mxc_params.missing_textures & 4u) != 0u;
    float v20 = mxc_sample_image(mxc_texture_2, param_12, param_13, param_14, param_15, param_16, param_17).x;
    float v21 = 0.2479999959468841552734375 * v20;
    vec2 param_18 = v4;
    vec4 param_19 = vec4(0.0);
    int param_20 = 2;
    int param_21 = 2;
    int param_22 = 0;
    bool param_23 = (mxc_params.missing_textures & 8u) != 0u;
    float v25 = mxc_sample_image(mxc_texture_3, param_18, param_19, param_20, param_21, param_22, param_23).x;
    float v26 = 0.082999996840953826904296875 * v25;
    vec2 param_24 = v4;
    vec4 param_25 = vec4(0.0);
    int param_26 = 2;
    int param_27 = 2;
    int param_28 = 0;
    bool param_29 = (mxc_params.missing_textures & 16u) != 0u;
    float v28 = mxc_sample_image(mxc_texture_4, param_24, param_25, param_26, param_27, param_28, param_29).x;
    float v29 = v26 + v28;
    float v31 = v29 - 0.3499999940395355224609375;
    float v32 = v31 * 0.082999996840953826904296875;
    float v34 = 0.787000000476837158203125 * v25;
    float v35 = v29 * v34;
    vec3 v36 = vec3(v32, 0.0, v35);
    vec3 v38 = v36 + vec3(0.0480653941631317138671875, 1.0, 0.661876022815704345703125);
    vec3 param_30 = v38;
    vec3 v39 = mxc_hsv_to_rgb(param_30);
    vec3 v40 = mix(v39, vec3(0.5637199878692626953125), vec3(v21));
    vec3 v41 = v40 * v28;
    vec3 v43 = vec3(0.2632730007171630859375) * v28;
    vec3 v44 = mix(v43, v41, vec3(v8));
    vec3 v45 = clamp(v44, vec3(0.0), vec3(1.0));
    vec3 v46 = clamp(v45, vec3(0.0), vec3(1.0));
    vec2 param_31 = v4;
    vec4 param_32 = vec4(0.0, 0.0, 0.0, 1.0);
    int param_33 = 2;
    int param_34 = 2;
    int param_35 = 0;
    bool param_36 = (mxc_params.missing_textures & 32u) != 0u;
    vec3 v48 = mxc_sample_image(mxc_texture_5, param_31, param_32, param_33, param_34, param_35, param_36).xyz;
    vec3 v49 = g.N;
    vec3 v50 = g.T;
    vec3 v51 = g.B;
    vec3 param_37 = v48;
    vec2 param_38 = vec2(1.0);
    vec3 param_39 = v49;
    vec3 param_40 = v50;
    vec3 param_41 = v51;
    vec3 v52 = mxc_normalmap(param_37, param_38, param_39, param_40, param_41);
    float v55 = v14 * v14;
    float v56 = clamp(v55, 1.0000000116860974230803549289703e-07, 1.0);
    vec2 v57 = vec2(v56, v56);
    c.emission = vec3(0.0);
    c.transparency = vec3(0.0);
    MxcLobe lobe0;
    lobe0.kind = 1;
    lobe0.mode = 1;
    vec3 param_42 = v52;
    vec3 param_43 = g.N;
    lobe0.N = mxc_safe_normalize(param_42, param_43);
    lobe0.T = v50;
    lobe0.alpha = v57;
    lobe0.eta = 1.5;
    lobe0.c0 = vec3(1.0);
    lobe0.c1 = vec3(1.0);
    lobe0.c2 = vec3(1.0);
    lobe0.p0 = 0.0;
    lobe0.p1 = 1.0;
    lobe0.film = vec3(0.0);
    lobe0.tau = vec3(0.0);
    lobe0.tauEta = 1.0;
    vec3 param_44 = lobe0.N;
    vec3 param_45 = lobe0.T;
    mat3 param_46 = mxc_frame(param_44, param_45);
    vec3 param_47 = wo;
    MxcLobe param_48 = lobe0;
    vec3 param_49 = mxc_to_local(param_46, param_47);
    vec3 e1 = mxc_lobe_layer_albedo(param_48, param_49);
    vec3 w2 = vec3(1.0) - e1;
    MxcLobe lobe3;
    lobe3.kind = 4;
    lobe3.mode = 1;
    vec3 param_50 = v52;
    vec3 param_51 = g.N;
    lobe3.N = mxc_safe_normalize(param_50, param_51);
    lobe3.T = g.T;
    lobe3.alpha = vec2(0.0);
    lobe3.eta = 1.5;
    lobe3.c0 = v46;
    lobe3.c1 = vec3(1.0);
    lobe3.c2 = vec3(1.0);
    lobe3.p0 = 0.0;
    lobe3.p1 = 1.0;
    lobe3.film = vec3(0.0);
    lobe3.tau = vec3(0.0);
    lobe3.tauEta = 1.0;
    lobe0.weight = vec3(1.0);
    c.lobes[0] = lobe0;
    lobe3.weight = w2;
    c.lobes[1] = lobe3;
    c.count = 2;
    MxcClosure param_52 = c;
    vec3 param_53 = wo;
    mxc_closure_prepare(param_52, param_53);
    c = param_52;
}

int mxc_light_count()
{
    int _4485;
    if (_252)
    {
        _4485 = MXC_LIGHT_COUNT;
    }
    else
    {
        _4485 = mxc_view.counts.x;
    }
    return min(_4485, 8);
}

int mxc_light_kinds()
{
    return _255;
}

int mxc_environment_code()
{
    int _4477;
    if (_250)
    {
        _4477 = MXC_ENVIRONMENT;
    }
    else
    {
        _4477 = mxc_view.counts.y;
    }
    return _4477;
}

float mxc_uniform(inout uint seed)
{
    uint param = seed;
    seed = mxc_pcg(param);
    return float(seed >> uint(8)) * 5.9604644775390625e-08;
}

float mxc_radical_inverse(inout uint i, uint base)
{
    if (base == 2u)
    {
        return float(bitfieldReverse(i) >> uint(8)) * 5.9604644775390625e-08;
    }
    float inv = 1.0 / float(base);
    float f = inv;
    float r = 0.0;
    for (; i > 0u; i /= base)
    {
        r += (f * float(i % base));
        f *= inv;
    }
    return min(r, 0.999999940395355224609375);
}

vec3 mxc_sample_cosine(vec2 u)
{
    float r = sqrt(u.x);
    float phi = 6.283185482025146484375 * u.y;
    float param = 1.0 - u.x;
    return vec3(r * cos(phi), r * sin(phi), mxc_safe_sqrt(param));
}

vec2 mxc_rough_alpha(vec2 alpha)
{
    return max(alpha, vec2(9.9999997473787516355514526367188e-05));
}

float mxc_ggx_d(vec3 m, inout vec2 alpha)
{
    if (m.z <= 0.0)
    {
        return 0.0;
    }
    vec2 param = alpha;
    alpha = mxc_rough_alpha(param);
    vec3 s = vec3(m.x / alpha.x, m.y / alpha.y, m.z);
    float d = dot(s, s);
    return 1.0 / ((((3.1415927410125732421875 * alpha.x) * alpha.y) * d) * d);
}

float mxc_sqr(float x)
{
    return x * x;
}

float mxc_ggx_lambda(vec3 v, inout vec2 alpha)
{
    vec2 param = alpha;
    alpha = mxc_rough_alpha(param);
    float z2 = v.z * v.z;
    if (z2 <= 0.0)
    {
        return 10000000000.0;
    }
    float param_1 = alpha.x * v.x;
    float param_2 = alpha.y * v.y;
    float a2 = (mxc_sqr(param_1) + mxc_sqr(param_2)) / z2;
    return 0.5 * ((-1.0) + sqrt(1.0 + a2));
}

float mxc_ggx_g2(vec3 wo, vec3 wi, vec2 alpha)
{
    vec3 param = wo;
    vec2 param_1 = alpha;
    float _1295 = mxc_ggx_lambda(param, param_1);
    vec3 param_2 = wi;
    vec2 param_3 = alpha;
    float _1299 = mxc_ggx_lambda(param_2, param_3);
    return 1.0 / ((1.0 + _1295) + _1299);
}

vec3 mxc_microfacet_reflect(MxcLobe l, vec3 wo, vec3 wi)
{
    bool _1993 = wo.z <= 0.0;
    bool _2000;
    if (!_1993)
    {
        _2000 = wi.z <= 0.0;
    }
    else
    {
        _2000 = _1993;
    }
    bool _2007;
    if (!_2000)
    {
        vec2 param = l.alpha;
        _2007 = mxc_is_delta(param);
    }
    else
    {
        _2007 = _2000;
    }
    if (_2007)
    {
        return vec3(0.0);
    }
    vec3 h = normalize(wo + wi);
    MxcLobe param_1 = l;
    float param_2 = max(dot(wo, h), 0.0);
    bool param_3 = true;
    vec3 f = mxc_lobe_fresnel(param_1, param_2, param_3);
    if (l.kind == 1)
    {
        f *= l.c0;
    }
    vec3 param_4 = h;
    vec2 param_5 = l.alpha;
    float _2033 = mxc_ggx_d(param_4, param_5);
    vec3 param_6 = wo;
    vec3 param_7 = wi;
    vec2 param_8 = l.alpha;
    return ((f * _2033) * mxc_ggx_g2(param_6, param_7, param_8)) / vec3(4.0 * wo.z);
}

float mxc_fon(float sigma, vec3 wo, vec3 wi)
{
    float a = 1.0 / (1.0 + (0.2877933979034423828125 * sigma));
    float s = dot(wi, wo) - (wi.z * wo.z);
    float _2054;
    if (s > 0.0)
    {
        _2054 = max(max(wi.z, wo.z), 9.9999999747524270787835121154785e-07);
    }
    else
    {
        _2054 = 1.0;
    }
    float t = _2054;
    return (a + (((sigma * a) * s) / t)) * 0.3183098733425140380859375;
}

vec3 mxc_lobe_eval(MxcLobe l, vec3 wo, vec3 wi)
{
    switch (l.kind)
    {
        case 1:
        {
            if ((wo.z * wi.z) > 0.0)
            {
                if ((l.mode & 1) == 0)
                {
                    return vec3(0.0);
                }
                if (wo.z < 0.0)
                {
                    MxcLobe m = l;
                    m.eta = 1.0 / l.eta;
                    m.c0 = vec3(1.0);
                    MxcLobe param = m;
                    vec3 param_1 = -wo;
                    vec3 param_2 = -wi;
                    return mxc_microfacet_reflect(param, param_1, param_2);
                }
                MxcLobe param_3 = l;
                vec3 param_4 = wo;
                vec3 param_5 = wi;
                return mxc_microfacet_reflect(param_3, param_4, param_5);
            }
            return vec3(0.0);
        }
        case 2:
        case 3:
        {
            bool _2756 = l.kind == 3;
            bool _2763;
            if (_2756)
            {
                _2763 = (l.mode & 1) == 0;
            }
            else
            {
                _2763 = _2756;
            }
            if (_2763)
            {
                return vec3(0.0);
            }
            MxcLobe param_6 = l;
            vec3 param_7 = wo;
            vec3 param_8 = wi;
            return mxc_microfacet_reflect(param_6, param_7, param_8);
        }
        case 4:
        {
            bool _2772 = wo.z > 0.0;
            bool _2778;
            if (_2772)
            {
                _2778 = wi.z > 0.0;
            }
            else
            {
                _2778 = _2772;
            }
            vec3 _2708;
            if (_2778)
            {
                float param_9 = l.p0;
                vec3 param_10 = wo;
                vec3 param_11 = wi;
                _2708 = (l.c0 * mxc_fon(param_9, param_10, param_11)) * wi.z;
            }
            else
            {
                _2708 = vec3(0.0);
            }
            return _2708;
        }
        default:
        {
            return vec3(0.0);
        }
    }
}

float mxc_ggx_g1(vec3 v, vec2 alpha)
{
    vec3 param = v;
    vec2 param_1 = alpha;
    float _1281 = mxc_ggx_lambda(param, param_1);
    return 1.0 / (1.0 + _1281);
}

float mxc_ggx_pdf_vndf(vec3 wo, vec3 m, vec2 alpha)
{
    if (wo.z <= 0.0)
    {
        return 0.0;
    }
    vec3 param = wo;
    vec2 param_1 = alpha;
    vec3 param_2 = m;
    vec2 param_3 = alpha;
    float _1454 = mxc_ggx_d(param_2, param_3);
    return ((mxc_ggx_g1(param, param_1) * max(dot(wo, m), 0.0)) * _1454) / wo.z;
}

float mxc_mean(vec3 c)
{
    return ((c.x + c.y) + c.z) * 0.3333333432674407958984375;
}

float mxc_lobe_pdf(MxcLobe l, vec3 wo, vec3 wi)
{
    switch (l.kind)
    {
        case 1:
        case 2:
        case 3:
        {
            vec2 param = l.alpha;
            if (mxc_is_delta(param))
            {
                return 0.0;
            }
            bool above = wo.z > 0.0;
            vec3 _2802;
            if (above)
            {
                _2802 = wo;
            }
            else
            {
                _2802 = -wo;
            }
            vec3 o = _2802;
            vec3 _2804;
            if (above)
            {
                _2804 = wi;
            }
            else
            {
                _2804 = -wi;
            }
            vec3 i = _2804;
            if (i.z > 0.0)
            {
                vec3 h = normalize(o + i);
                vec3 param_1 = o;
                vec3 param_2 = h;
                vec2 param_3 = l.alpha;
                float p = mxc_ggx_pdf_vndf(param_1, param_2, param_3) / (4.0 * max(dot(o, h), 9.9999999747524270787835121154785e-07));
                if (l.kind == 2)
                {
                    return p;
                }
                if ((l.mode & 1) == 0)
                {
                    return 0.0;
                }
                MxcLobe param_4 = l;
                float param_5 = max(dot(o, h), 0.0);
                bool param_6 = above;
                vec3 param_7 = mxc_lobe_fresnel(param_4, param_5, param_6);
                float fr = mxc_mean(param_7);
                MxcLobe param_8 = l;
                bool _2904 = mxc_lobe_transmits(param_8);
                bool _2911;
                if (_2904)
                {
                    _2911 = (l.mode & 1) != 0;
                }
                else
                {
                    _2911 = _2904;
                }
                return p * (_2911 ? fr : 1.0);
            }
            return 0.0;
        }
        default:
        {
            bool _2824 = wo.z > 0.0;
            bool _2830;
            if (_2824)
            {
                _2830 = wi.z > 0.0;
            }
            else
            {
                _2830 = _2824;
            }
            float _2816;
            if (_2830)
            {
                _2816 = wi.z * 0.3183098733425140380859375;
            }
            else
            {
                _2816 = 0.0;
            }
            return _2816;
        }
    }
}

vec3 mxc_ggx_sample_vndf(vec3 wo, inout vec2 alpha, vec2 u)
{
    vec2 param = alpha;
    alpha = mxc_rough_alpha(param);
    vec3 vh = normalize(vec3(alpha.x * wo.x, alpha.y * wo.y, wo.z));
    float lensq = (vh.x * vh.x) + (vh.y * vh.y);
    vec3 _1311;
    if (lensq > 0.0)
    {
        _1311 = vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq);
    }
    else
    {
        _1311 = vec3(1.0, 0.0, 0.0);
    }
    vec3 t1 = _1311;
    vec3 t2 = cross(vh, t1);
    float r = sqrt(u.x);
    float phi = 6.283185482025146484375 * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + vh.z);
    float param_1 = 1.0 - (p1 * p1);
    p2 = ((1.0 - s) * mxc_safe_sqrt(param_1)) + (s * p2);
    float param_2 = (1.0 - (p1 * p1)) - (p2 * p2);
    vec3 nh = ((t1 * p1) + (t2 * p2)) + (vh * mxc_safe_sqrt(param_2));
    return normalize(vec3(alpha.x * nh.x, alpha.y * nh.y, max(nh.z, 0.0)));
}

MxcLobeSample mxc_lobe_sample(MxcLobe l, vec3 wo, vec3 u)
{
    MxcLobeSample s;
    s.valid = false;
    s.delta = false;
    s.pdf = 0.0;
    s.value = vec3(0.0);
    s.wi = vec3(0.0, 0.0, 1.0);
    switch (l.kind)
    {
        case 1:
        case 2:
        case 3:
        {
            bool above = wo.z > 0.0;
            vec3 _2923;
            if (above)
            {
                _2923 = wo;
            }
            else
            {
                _2923 = -wo;
            }
            vec3 o = _2923;
            if (o.z <= 0.0)
            {
                return s;
            }
            vec2 param = l.alpha;
            bool delta = mxc_is_delta(param);
            vec3 _2927;
            if (delta)
            {
                _2927 = vec3(0.0, 0.0, 1.0);
            }
            else
            {
                vec3 param_1 = o;
                vec2 param_2 = l.alpha;
                vec2 param_3 = u.xy;
                vec3 _3028 = mxc_ggx_sample_vndf(param_1, param_2, param_3);
                _2927 = _3028;
            }
            vec3 m = _2927;
            float hm = dot(o, m);
            bool _3035 = l.kind == 1;
            bool _3042;
            if (!_3035)
            {
                _3042 = l.kind == 3;
            }
            else
            {
                _3042 = _3035;
            }
            bool _3047;
            if (_3042)
            {
                MxcLobe param_4 = l;
                _3047 = mxc_lobe_transmits(param_4);
            }
            else
            {
                _3047 = _3042;
            }
            bool transmits = _3047;
            bool _3050 = l.kind == 2;
            bool _3058;
            if (!_3050)
            {
                _3058 = (l.mode & 1) != 0;
            }
            else
            {
                _3058 = _3050;
            }
            bool reflects = _3058;
            MxcLobe param_5 = l;
            float param_6 = max(hm, 0.0);
            bool param_7 = above;
            vec3 f = mxc_lobe_fresnel(param_5, param_6, param_7);
            float _2940;
            if (transmits)
            {
                vec3 param_8 = f;
                _2940 = mxc_mean(param_8);
            }
            else
            {
                _2940 = 1.0;
            }
            float fr = _2940;
            float _2943;
            if (transmits)
            {
                _2943 = reflects ? fr : 0.0;
            }
            else
            {
                _2943 = 1.0;
            }
            float pReflect = _2943;
            if (u.z < pReflect)
            {
                vec3 i = reflect(-o, m);
                if (i.z <= 0.0)
                {
                    return s;
                }
                vec3 _2945;
                if (above)
                {
                    _2945 = i;
                }
                else
                {
                    _2945 = -i;
                }
                s.wi = _2945;
                s.delta = delta;
                if (delta)
                {
                    vec3 _2947;
                    if (l.kind == 1)
                    {
                        vec3 _2948;
                        if (above)
                        {
                            _2948 = l.c0;
                        }
                        else
                        {
                            _2948 = vec3(1.0);
                        }
                        _2947 = _2948;
                    }
                    else
                    {
                        _2947 = vec3(1.0);
                    }
                    vec3 tint = _2947;
                    s.value = f * tint;
                    s.pdf = pReflect;
                }
                else
                {
                    MxcLobe param_9 = l;
                    vec3 param_10 = wo;
                    vec3 param_11 = s.wi;
                    s.value = mxc_lobe_eval(param_9, param_10, param_11);
                    MxcLobe param_12 = l;
                    vec3 param_13 = wo;
                    vec3 param_14 = s.wi;
                    s.pdf = mxc_lobe_pdf(param_12, param_13, param_14);
                }
                s.valid = s.pdf > 0.0;
                return s;
            }
            return s;
        }
        default:
        {
            if (wo.z <= 0.0)
            {
                return s;
            }
            vec2 param_15 = u.xy;
            s.wi = mxc_sample_cosine(param_15);
            MxcLobe param_16 = l;
            vec3 param_17 = wo;
            vec3 param_18 = s.wi;
            s.value = mxc_lobe_eval(param_16, param_17, param_18);
            MxcLobe param_19 = l;
            vec3 param_20 = wo;
            vec3 param_21 = s.wi;
            s.pdf = mxc_lobe_pdf(param_19, param_20, param_21);
            s.valid = s.pdf > 0.0;
            return s;
        }
    }
}

vec3 mxc_to_world(mat3 frame, vec3 v)
{
    return ((frame[0] * v.x) + (frame[1] * v.y)) + (frame[2] * v.z);
}

vec3 mxc_lobe_absorption(MxcLobe l, float mu)
{
    return vec3(1.0);
}

MxcSample mxc_closure_sample_direction(MxcClosure c, vec3 wo, vec3 u)
{
    MxcSample s;
    s.valid = false;
    s.delta = false;
    s.evaluate = false;
    s.pdf = 0.0;
    s.weight = vec3(0.0);
    s.wi = wo;
    float total = c.choiceTotal;
    if ((c.count == 0) || (total <= 0.0))
    {
        return s;
    }
    float x = u.z * total;
    int chosen = -1;
    float before = 0.0;
    float p = 0.0;
    float lastBefore = 0.0;
    int last = -1;
    for (int k = 0; k < c.count; k++)
    {
        float pk = c.choice[k];
        if (pk <= 0.0)
        {
            continue;
        }
        if (x < (before + pk))
        {
            chosen = k;
            p = pk;
            break;
        }
        last = k;
        lastBefore = before;
        before += pk;
    }
    if (chosen < 0)
    {
        chosen = max(last, 0);
        p = c.choice[chosen];
        before = lastBefore;
    }
    if (p <= 0.0)
    {
        return s;
    }
    float uz = clamp((x - before) / p, 0.0, 0.999999940395355224609375);
    MxcLobe l = c.lobes[chosen];
    vec3 param = l.N;
    vec3 param_1 = l.T;
    mat3 frame = mxc_frame(param, param_1);
    mat3 param_2 = frame;
    vec3 param_3 = wo;
    vec3 o = mxc_to_local(param_2, param_3);
    float q = c.msPick[chosen];
    bool shaped = uz < q;
    bool reflected = true;
    if (shaped)
    {
        float v = uz / q;
        float split = c.msSplit[chosen];
        reflected = v < split;
        float _3697;
        if (reflected)
        {
            _3697 = v / max(split, 9.9999999747524270787835121154785e-07);
        }
        else
        {
            _3697 = (v - split) / max(1.0 - split, 9.9999999747524270787835121154785e-07);
        }
        uz = _3697;
    }
    else
    {
        uz = (uz - q) / (1.0 - q);
    }
    MxcLobe _3699;
    if (shaped)
    {
        MxcLobe param_4 = l;
        bool param_5 = !reflected;
        _3699 = mxc_ms_lobe(param_4, param_5);
    }
    else
    {
        _3699 = l;
    }
    MxcLobe m = _3699;
    MxcLobe param_6 = m;
    vec3 param_7 = o;
    vec3 param_8 = vec3(u.xy, min(uz, 0.999999940395355224609375));
    MxcLobeSample ls = mxc_lobe_sample(param_6, param_7, param_8);
    if (!ls.valid)
    {
        return s;
    }
    mat3 param_9 = frame;
    vec3 param_10 = ls.wi;
    s.wi = mxc_to_world(param_9, param_10);
    if (ls.delta)
    {
        s.delta = true;
        s.pdf = (ls.pdf * p) / total;
        MxcLobe param_11 = l;
        float param_12 = abs(ls.wi.z);
        s.weight = (((l.weight * c.ms[chosen]) * mxc_lobe_absorption(param_11, param_12)) * ls.value) / vec3(s.pdf);
        s.valid = s.pdf > 0.0;
        return s;
    }
    s.evaluate = true;
    s.valid = true;
    return s;
}

vec3 mxc_exit_direction(vec3 d, vec3 t)
{
    vec3 axis = cross(d, t);
    float s = length(axis);
    if (s < 9.9999999747524270787835121154785e-07)
    {
        return t;
    }
    axis /= vec3(s);
    float c = dot(d, t);
    return ((t * c) + (cross(axis, t) * s)) + ((axis * dot(axis, t)) * (1.0 - c));
}

vec3 mxc_sky(vec3 d)
{
    float y = clamp(d.y, -1.0, 1.0);
    vec3 horizon = vec3(1.0, 0.959999978542327880859375, 0.89999997615814208984375);
    vec3 zenith = vec3(0.300000011920928955078125, 0.5, 0.949999988079071044921875);
    vec3 ground = vec3(0.1599999964237213134765625, 0.14499999582767486572265625, 0.12999999523162841796875);
    if (y >= 0.0)
    {
        return mix(horizon, zenith, vec3(sqrt(y)));
    }
    return mix(horizon, ground, vec3(sqrt(-y)));
}

vec3 mxc_env_to_map(vec3 w, float angle)
{
    float c = cos(angle);
    float s = sin(angle);
    return vec3((c * w.x) - (s * w.z), w.y, (s * w.x) + (c * w.z));
}

vec2 mxc_env_uv(vec3 d)
{
    float _4187;
    if ((abs(d.x) + abs(d.z)) > 9.9999999600419720025001879548654e-13)
    {
        _4187 = 0.5 + (atan(d.x, -d.z) * 0.15915493667125701904296875);
    }
    else
    {
        _4187 = 0.5;
    }
    float u = _4187;
    float v = atan(length(d.xz), d.y) * 0.3183098733425140380859375;
    return vec2(u, v);
}

vec3 mxc_env_lookup(vec3 d)
{
    vec3 param = d;
    return textureLod(mxc_env_radiance, mxc_env_uv(param), 0.0).xyz;
}

vec3 mxc_environment(vec3 d)
{
    int code = mxc_environment_code();
    if (code == 1)
    {
        return vec3(mxc_view.environment.x);
    }
    if (code == 2)
    {
        vec3 param = d;
        return mxc_sky(param) * mxc_view.environment.x;
    }
    if (code == 3)
    {
        vec3 param_1 = d;
        float param_2 = mxc_view.environment.z;
        vec3 param_3 = mxc_env_to_map(param_1, param_2);
        return mxc_env_lookup(param_3) * mxc_view.environment.x;
    }
    return vec3(0.0);
}

uint mxc_env_cell(vec3 d)
{
    vec3 param = d;
    vec2 uv = mxc_env_uv(param);
    uvec2 size = max(_233.mxc_env_size.xy, uvec2(1u));
    uint i = min(uint(max(uv.x, 0.0) * float(size.x)), (size.x - 1u));
    uint j = min(uint(max(uv.y, 0.0) * float(size.y)), (size.y - 1u));
    return (j * size.x) + i;
}

float mxc_env_pdf(vec3 d)
{
    vec3 param = d;
    return _233.mxc_env_cells[mxc_env_cell(param)].z;
}

float mxc_power_heuristic(float a, float b)
{
    float a2 = a * a;
    float b2 = b * b;
    float _4577;
    if ((a2 + b2) > 0.0)
    {
        _4577 = a2 / (a2 + b2);
    }
    else
    {
        _4577 = 0.0;
    }
    return _4577;
}

vec3 mxc_env_sample(vec4 u, out float pdf)
{
    uvec2 size = max(_233.mxc_env_size.xy, uvec2(1u));
    uint n = size.x * size.y;
    uint k = min(uint(u.x * float(n)), (n - 1u));
    vec4 cell = _233.mxc_env_cells[k];
    if (u.y >= cell.x)
    {
        k = min(floatBitsToUint(cell.y), (n - 1u));
    }
    pdf = _233.mxc_env_cells[k].z;
    uint i = k % size.x;
    uint j = k / size.x;
    float phi = 6.283185482025146484375 * (((float(i) + u.z) / float(size.x)) - 0.5);
    float y0 = cos((3.1415927410125732421875 * float(j)) / float(size.y));
    float y1 = cos((3.1415927410125732421875 * float(j + 1u)) / float(size.y));
    float y = mix(y0, y1, u.w);
    float param = 1.0 - (y * y);
    float r = mxc_safe_sqrt(param);
    return vec3(r * sin(phi), y, (-r) * cos(phi));
}

vec3 mxc_env_to_world(vec3 m, float angle)
{
    float c = cos(angle);
    float s = sin(angle);
    return vec3((c * m.x) + (s * m.z), m.y, ((-s) * m.x) + (c * m.z));
}

vec3 mxc_closure_eval_pdf(MxcClosure c, vec3 wo, vec3 wi, bool wantPdf, inout float pdf)
{
    vec3 f = vec3(0.0);
    float p = 0.0;
    MxcLobe _3477;
    vec3 _3481;
    vec3 _3482;
    vec3 _3483;
    float _3488;
    float _3489;
    for (int k = 0; k < c.count; k++)
    {
        MxcLobe l = c.lobes[k];
        if (all(equal(l.weight, vec3(0.0))))
        {
            continue;
        }
        vec3 param = l.N;
        vec3 param_1 = l.T;
        mat3 frame = mxc_frame(param, param_1);
        mat3 param_2 = frame;
        vec3 param_3 = wo;
        vec3 o = mxc_to_local(param_2, param_3);
        mat3 param_4 = frame;
        vec3 param_5 = wi;
        vec3 i = mxc_to_local(param_4, param_5);
        vec3 fk = vec3(0.0);
        float pk = 0.0;
        int passes = (c.msPick[k] > 0.0) ? 2 : 1;
        for (int pass = 0; pass < passes; pass++)
        {
            bool shaped = pass == 1;
            if (shaped)
            {
                MxcLobe param_6 = l;
                bool param_7 = i.z < 0.0;
                _3477 = mxc_ms_lobe(param_6, param_7);
            }
            else
            {
                _3477 = l;
            }
            MxcLobe m = _3477;
            if (shaped)
            {
                if (i.z > 0.0)
                {
                    _3482 = c.msLobe[k];
                }
                else
                {
                    _3482 = c.msLobeT[k];
                }
                _3481 = _3482;
            }
            else
            {
                if ((o.z * i.z) < 0.0)
                {
                    _3483 = vec3(c.msT[k]);
                }
                else
                {
                    _3483 = c.ms[k];
                }
                _3481 = _3483;
            }
            vec3 scale = _3481;
            MxcLobe param_8 = m;
            vec3 param_9 = o;
            vec3 param_10 = i;
            fk += (scale * mxc_lobe_eval(param_8, param_9, param_10));
            if (wantPdf)
            {
                if (shaped)
                {
                    if (i.z > 0.0)
                    {
                        _3489 = c.msSplit[k];
                    }
                    else
                    {
                        _3489 = 1.0 - c.msSplit[k];
                    }
                    _3488 = c.msPick[k] * _3489;
                }
                else
                {
                    _3488 = 1.0 - c.msPick[k];
                }
                float share = _3488;
                MxcLobe param_11 = m;
                vec3 param_12 = o;
                vec3 param_13 = i;
                pk += (share * mxc_lobe_pdf(param_11, param_12, param_13));
            }
        }
        MxcLobe param_14 = l;
        float param_15 = abs(i.z);
        f += ((l.weight * mxc_lobe_absorption(param_14, param_15)) * fk);
        if (wantPdf)
        {
            p += (c.choice[k] * pk);
        }
    }
    float _3495;
    if (c.choiceTotal > 0.0)
    {
        _3495 = p / c.choiceTotal;
    }
    else
    {
        _3495 = 0.0;
    }
    pdf = _3495;
    return f;
}

void main()
{
    mxc_texture_footprint = 1.0;
    MxcGeometry g;
    g.P = vPosition;
    g.Pobj = vObjectPosition;
    vec3 param = vNormal;
    vec3 param_1 = vec3(0.0, 0.0, 1.0);
    vec3 N = mxc_safe_normalize(param, param_1);
    if (!gl_FrontFacing)
    {
        N = -N;
    }
    vec3 param_2 = mxc_view.eye.xyz - vPosition;
    vec3 param_3 = N;
    vec3 wo = mxc_safe_normalize(param_2, param_3);
    float facing = dot(wo, N);
    if (facing < 0.00999999977648258209228515625)
    {
        N = normalize(N + (wo * (0.00999999977648258209228515625 - facing)));
    }
    float handedness = (vTangent.w < 0.0) ? (-1.0) : 1.0;
    vec3 param_4 = N;
    vec3 param_5 = vTangent.xyz;
    mat3 frame = mxc_frame(param_4, param_5);
    g.N = N;
    g.T = frame[0];
    g.B = frame[1] * handedness;
    vec3 param_6 = vObjectNormal;
    vec3 param_7 = vec3(0.0, 0.0, 1.0);
    g.Nobj = mxc_safe_normalize(param_6, param_7);
    vec3 param_8 = g.Nobj;
    vec3 param_9 = vObjectTangent;
    mat3 objectFrame = mxc_frame(param_8, param_9);
    g.Tobj = objectFrame[0];
    g.Bobj = objectFrame[1] * handedness;
    g.uv = vUv;
    g.color = vec4(1.0);
    g.objectToWorld = mxc_view.objectToWorld;
    g.frame = mxc_params.frame;
    g.time = mxc_params.time;
    mxc_texture_footprint = mxc_view.jitter.z;
    if (!(mxc_texture_footprint > 0.0))
    {
        mxc_texture_footprint = 1.0;
    }
    uint param_10 = uint(mxc_view.counts.z) + 7u;
    uint param_11 = uint(gl_FragCoord.y) + mxc_pcg(param_10);
    uint param_12 = uint(gl_FragCoord.x) ^ mxc_pcg(param_11);
    uint param_13 = mxc_pcg(param_12);
    mxc_closure_seed(param_13);
    MxcGeometry param_14 = g;
    vec3 param_15 = wo;
    MxcClosure param_16;
    mxc_material_closure(param_14, param_15, param_16);
    MxcClosure c = param_16;
    vec3 radiance = c.emission * mxc_view.environment.y;
    int lights = mxc_light_count();
    int kinds = mxc_light_kinds();
    bool image = mxc_environment_code() == 3;
    int _289;
    if (mxc_environment_code() != 0)
    {
        _289 = max(mxc_view.counts.w, 1);
    }
    else
    {
        _289 = 0;
    }
    int n = _289;
    uint param_17 = uint(mxc_view.counts.z);
    uint param_18 = uint(gl_FragCoord.y) + mxc_pcg(param_17);
    uint param_19 = uint(gl_FragCoord.x) + mxc_pcg(param_18);
    uint seed = mxc_pcg(param_19);
    uint param_20 = uint(gl_FragCoord.y) + 2654435769u;
    uint param_21 = uint(gl_FragCoord.x) ^ mxc_pcg(param_20);
    uint pixel = mxc_pcg(param_21);
    uint param_22 = pixel;
    float _537 = mxc_uniform(param_22);
    pixel = param_22;
    uint param_23 = pixel;
    float _541 = mxc_uniform(param_23);
    pixel = param_23;
    uint param_24 = pixel;
    float _544 = mxc_uniform(param_24);
    pixel = param_24;
    uint param_25 = pixel;
    float _547 = mxc_uniform(param_25);
    pixel = param_25;
    vec4 shift = vec4(_537, _541, _544, _547);
    vec3 sum = vec3(0.0);
    int _306;
    MxcSample smp;
    vec3 _323;
    vec3 _324;
    float _329;
    float param_49;
    int _353;
    float param_59;
    float _369;
    for (int b = 0; b < max(n, int(lights > 0)); b++)
    {
        int batchLights = (b == 0) ? lights : 0;
        if (b < n)
        {
            _306 = 1 + int(image);
        }
        else
        {
            _306 = 0;
        }
        int batchSamples = _306;
        uint index = (uint(mxc_view.counts.z) * uint(max(n, 1))) + uint(b);
        uint param_26 = index;
        uint param_27 = 2u;
        float _587 = mxc_radical_inverse(param_26, param_27);
        uint param_28 = index;
        uint param_29 = 3u;
        float _590 = mxc_radical_inverse(param_28, param_29);
        uint param_30 = index;
        uint param_31 = 5u;
        float _592 = mxc_radical_inverse(param_30, param_31);
        uint param_32 = index;
        uint param_33 = 7u;
        float _594 = mxc_radical_inverse(param_32, param_33);
        vec4 choice = fract(vec4(_587, _590, _592, _594) + shift);
        smp.valid = false;
        smp.evaluate = false;
        smp.delta = false;
        smp.pdf = 0.0;
        smp.weight = vec3(0.0);
        smp.wi = N;
        if (n > 0)
        {
            MxcClosure param_34 = c;
            vec3 param_35 = wo;
            vec3 param_36 = vec3(choice.z, choice.w, choice.x);
            smp = mxc_closure_sample_direction(param_34, param_35, param_36);
        }
        bool above = dot(smp.wi, N) > 0.0;
        if (smp.valid)
        {
            if (above)
            {
                _324 = smp.wi;
            }
            else
            {
                vec3 param_37 = -wo;
                vec3 param_38 = smp.wi;
                _324 = mxc_exit_direction(param_37, param_38);
            }
            vec3 param_39 = _324;
            _323 = mxc_environment(param_39);
        }
        else
        {
            _323 = vec3(0.0);
        }
        vec3 seen = _323;
        bool _652 = (b < n) && smp.valid;
        bool _658;
        if (_652)
        {
            _658 = !smp.evaluate;
        }
        else
        {
            _658 = _652;
        }
        if (_658)
        {
            bool _663 = image && above;
            bool _669;
            if (_663)
            {
                _669 = !smp.delta;
            }
            else
            {
                _669 = _663;
            }
            if (_669)
            {
                vec3 param_40 = smp.wi;
                float param_41 = mxc_view.environment.z;
                vec3 param_42 = mxc_env_to_map(param_40, param_41);
                float param_43 = smp.pdf;
                float param_44 = mxc_env_pdf(param_42);
                _329 = mxc_power_heuristic(param_43, param_44);
            }
            else
            {
                _329 = 1.0;
            }
            float w = _329;
            sum += ((smp.weight * w) * seen);
        }
        vec3 m = vec3(0.0);
        float lightPdf = 0.0;
        vec3 imageWi = N;
        vec3 imageSeen = vec3(0.0);
        if (image && (b < n))
        {
            uint param_45 = seed;
            float _705 = mxc_uniform(param_45);
            seed = param_45;
            uint param_46 = seed;
            float _708 = mxc_uniform(param_46);
            seed = param_46;
            uint param_47 = seed;
            float _711 = mxc_uniform(param_47);
            seed = param_47;
            vec4 v = vec4(choice.y, _705, _708, _711);
            vec4 param_48 = v;
            vec3 _715 = mxc_env_sample(param_48, param_49);
            lightPdf = param_49;
            m = _715;
            vec3 param_50 = m;
            float param_51 = mxc_view.environment.z;
            imageWi = mxc_env_to_world(param_50, param_51);
            bool _724 = lightPdf > 0.0;
            bool _731;
            if (_724)
            {
                _731 = dot(imageWi, N) > 0.0;
            }
            else
            {
                _731 = _724;
            }
            if (_731)
            {
                vec3 param_52 = imageWi;
                imageSeen = mxc_environment(param_52);
            }
        }
        for (int j = 0; j < (batchLights + batchSamples); j++)
        {
            vec3 wi = N;
            vec3 incoming = vec3(0.0);
            bool use = true;
            if ((n == 0) || (j < batchLights))
            {
                _353 = 0;
            }
            else
            {
                _353 = (j == ((batchLights + 1) - 1)) ? 1 : 2;
            }
            int strategy = _353;
            if (strategy == 0)
            {
                vec4 light = mxc_view.lightVector[j];
                incoming = mxc_view.lightRadiance[j].xyz;
                bool _776 = kinds == 1;
                bool _789;
                if (!_776)
                {
                    bool _782 = (kinds & 1) != 0;
                    bool _788;
                    if (_782)
                    {
                        _788 = light.w == 0.0;
                    }
                    else
                    {
                        _788 = _782;
                    }
                    _789 = _788;
                }
                else
                {
                    _789 = _776;
                }
                bool directional = _789;
                if (directional)
                {
                    vec3 param_53 = light.xyz;
                    vec3 param_54 = N;
                    wi = mxc_safe_normalize(param_53, param_54);
                }
                else
                {
                    vec3 d = light.xyz - vPosition;
                    float d2 = max(dot(d, d), 9.9999999392252902907785028219223e-09);
                    wi = d * inversesqrt(d2);
                    incoming /= vec3(d2);
                    bool _816 = (kinds & 4) != 0;
                    bool _822;
                    if (_816)
                    {
                        _822 = light.w == 2.0;
                    }
                    else
                    {
                        _822 = _816;
                    }
                    if (_822)
                    {
                        vec4 spot = mxc_view.lightSpot[j];
                        incoming *= smoothstep(spot.w, mxc_view.lightRadiance[j].w, dot(-wi, spot.xyz));
                    }
                }
            }
            else
            {
                if (strategy == 1)
                {
                    wi = smp.wi;
                    incoming = seen;
                    use = smp.valid && smp.evaluate;
                }
                else
                {
                    wi = imageWi;
                    incoming = imageSeen;
                    bool _857 = lightPdf > 0.0;
                    bool _864;
                    if (_857)
                    {
                        _864 = dot(imageWi, N) > 0.0;
                    }
                    else
                    {
                        _864 = _857;
                    }
                    use = _864;
                }
            }
            MxcClosure param_55 = c;
            vec3 param_56 = wo;
            vec3 param_57 = wi;
            bool param_58 = strategy != 0;
            vec3 _870 = mxc_closure_eval_pdf(param_55, param_56, param_57, param_58, param_59);
            float pdf = param_59;
            vec3 f = _870;
            if (strategy == 0)
            {
                radiance += (f * incoming);
            }
            else
            {
                if (strategy == 1)
                {
                    if (use && (pdf > 0.0))
                    {
                        if (image && above)
                        {
                            vec3 param_60 = wi;
                            float param_61 = mxc_view.environment.z;
                            vec3 param_62 = mxc_env_to_map(param_60, param_61);
                            float param_63 = pdf;
                            float param_64 = mxc_env_pdf(param_62);
                            _369 = mxc_power_heuristic(param_63, param_64);
                        }
                        else
                        {
                            _369 = 1.0;
                        }
                        float w_1 = _369;
                        sum += (((f * w_1) / vec3(pdf)) * incoming);
                    }
                }
                else
                {
                    if (use)
                    {
                        vec3 param_65 = m;
                        float param_66 = mxc_env_pdf(param_65);
                        float param_67 = pdf;
                        float w_2 = mxc_power_heuristic(param_66, param_67);
                        sum += (((f * w_2) * incoming) / vec3(lightPdf));
                    }
                }
            }
        }
    }
    radiance += (sum / vec3(float(max(n, 1))));
    vec3 param_68 = c.transparency;
    float coverage = 1.0 - clamp(mxc_luminance(param_68), 0.0, 1.0);
    outColor = vec4(radiance, coverage);
}

// ==== vertex (main) ====
#version 450

#ifndef SPIRV_CROSS_CONSTANT_ID_0
#define SPIRV_CROSS_CONSTANT_ID_0 -1
#endif
const int MXC_ENVIRONMENT = SPIRV_CROSS_CONSTANT_ID_0;
#ifndef SPIRV_CROSS_CONSTANT_ID_1
#define SPIRV_CROSS_CONSTANT_ID_1 -1
#endif
const int MXC_LIGHT_COUNT = SPIRV_CROSS_CONSTANT_ID_1;
#ifndef SPIRV_CROSS_CONSTANT_ID_2
#define SPIRV_CROSS_CONSTANT_ID_2 -1
#endif
const int MXC_LIGHT_KINDS = SPIRV_CROSS_CONSTANT_ID_2;

layout(binding = 0, std140) uniform MxcView
{
    mat4 objectToWorld;
    mat4 normalToWorld;
    mat4 worldToClip;
    vec4 eye;
    vec4 jitter;
    vec4 lightVector[8];
    vec4 lightSpot[8];
    vec4 lightRadiance[8];
    ivec4 counts;
    vec4 environment;
} mxc_view;

layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec3 vPosition;
layout(location = 1) out vec3 vNormal;
layout(location = 1) in vec3 inNormal;
layout(location = 2) out vec4 vTangent;
layout(location = 2) in vec4 inTangent;
layout(location = 3) out vec2 vUv;
layout(location = 3) in vec2 inUv;
layout(location = 4) out vec3 vObjectPosition;
layout(location = 5) out vec3 vObjectNormal;
layout(location = 6) out vec3 vObjectTangent;

void main()
{
    precise vec4 _34 = mxc_view.objectToWorld * vec4(inPosition, 1.0);
    vec4 world = _34;
    vPosition = world.xyz;
    vNormal = mat3(mxc_view.normalToWorld[0].xyz, mxc_view.normalToWorld[1].xyz, mxc_view.normalToWorld[2].xyz) * inNormal;
    vTangent = vec4(mat3(mxc_view.objectToWorld[0].xyz, mxc_view.objectToWorld[1].xyz, mxc_view.objectToWorld[2].xyz) * inTangent.xyz, inTangent.w);
    vUv = inUv;
    vObjectPosition = inPosition;
    vObjectNormal = inNormal;
    vObjectTangent = inTangent.xyz;
    precise vec4 _96 = mxc_view.worldToClip * world;
    vec4 clip = _96;
    precise vec2 _105 = mxc_view.jitter.xy * clip.w;
    precise vec2 _108 = clip.xy + _105;
    clip.x = _108.x;
    clip.y = _108.y;
    gl_Position = clip;
}

