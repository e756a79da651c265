// ==== corpus/materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx: material M_BrickPattern, placements ====
// mxc_tables {"register":"t0","sampler":"s0","space":0}
// MxcView {"register":"b1","space":0}
// MxcParameters {"register":"t2","space":0}
// mxc_texture_0 {"register":"t5","sampler":"s5","space":0}
// mxc_texture_1 {"register":"t6","sampler":"s6","space":0}
// mxc_texture_2 {"register":"t7","sampler":"s7","space":0}
// mxc_texture_3 {"register":"t8","sampler":"s8","space":0}
// mxc_texture_4 {"register":"t9","sampler":"s9","space":0}
// mxc_texture_5 {"register":"t10","sampler":"s10","space":0}
// mxc_env_radiance {"register":"t0","sampler":"s0","space":1}
// MxcEnvDistribution {"register":"t1","space":1}
// ==== fragment (main) ====
struct MxcGeometry
{
    float3 P;
    float3 Pobj;
    float3 N;
    float3 Nobj;
    float3 T;
    float3 Tobj;
    float3 B;
    float3 Bobj;
    float2 uv;
    float4 color;
    float4x4 objectToWorld;
    float frame;
    float time;
};

struct MxcLobe
{
    int kind;
    int mode;
    float3 weight;
    float3 N;
    float3 T;
    float2 alpha;
    float eta;
    float etaAbove;
    float3 c0;
    float3 c1;
    float3 c2;
    float p0;
    float p1;
    float3 film;
    float3 tau;
    float tauEta;
};

struct MxcClosure
{
    MxcLobe lobes[2];
    int count;
    float choice[2];
    float choiceTotal;
    float3 ms[2];
    float msT[2];
    float3 msLobe[2];
    float3 msLobeT[2];
    float msPick[2];
    float msSplit[2];
    float3 emission;
    float3 transparency;
};

struct MxcSample
{
    float3 wi;
    float3 weight;
    float pdf;
    bool delta;
    bool evaluate;
    bool valid;
};

struct MxcLobeSample
{
    float3 wi;
    float3 value;
    float pdf;
    bool delta;
    bool valid;
};

#ifndef SPIRV_CROSS_CONSTANT_ID_0
#define SPIRV_CROSS_CONSTANT_ID_0 -1
#endif
static const int MXC_ENVIRONMENT = SPIRV_CROSS_CONSTANT_ID_0;
static const bool _252 = (MXC_ENVIRONMENT != (-1));
#ifndef SPIRV_CROSS_CONSTANT_ID_1
#define SPIRV_CROSS_CONSTANT_ID_1 -1
#endif
static const int MXC_LIGHT_COUNT = SPIRV_CROSS_CONSTANT_ID_1;
static const bool _254 = (MXC_LIGHT_COUNT != (-1));
#ifndef SPIRV_CROSS_CONSTANT_ID_2
#define SPIRV_CROSS_CONSTANT_ID_2 -1
#endif
static const int MXC_LIGHT_KINDS = SPIRV_CROSS_CONSTANT_ID_2;
static const bool _256 = (MXC_LIGHT_KINDS != (-1));
static const int _257 = _256 ? MXC_LIGHT_KINDS : 7;

cbuffer MxcView : register(b1, space0)
{
    row_major float4x4 mxc_view_objectToWorld : packoffset(c0);
    row_major float4x4 mxc_view_normalToWorld : packoffset(c4);
    row_major float4x4 mxc_view_worldToClip : packoffset(c8);
    float4 mxc_view_eye : packoffset(c12);
    float4 mxc_view_jitter : packoffset(c13);
    float4 mxc_view_lightVector[8] : packoffset(c14);
    float4 mxc_view_lightSpot[8] : packoffset(c22);
    float4 mxc_view_lightRadiance[8] : packoffset(c30);
    int4 mxc_view_counts : packoffset(c38);
    float4 mxc_view_environment : packoffset(c39);
};

ByteAddressBuffer mxc_params : register(t2, space0);
ByteAddressBuffer _235 : register(t1, space1);
Texture2D<float4> mxc_tables : register(t0, space0);
SamplerState _mxc_tables_sampler : register(s0, space0);
Texture2D<float4> mxc_texture_0 : register(t5, space0);
SamplerState _mxc_texture_0_sampler : register(s5, space0);
Texture2D<float4> mxc_texture_1 : register(t6, space0);
SamplerState _mxc_texture_1_sampler : register(s6, space0);
Texture2D<float4> mxc_texture_2 : register(t7, space0);
SamplerState _mxc_texture_2_sampler : register(s7, space0);
Texture2D<float4> mxc_texture_3 : register(t8, space0);
SamplerState _mxc_texture_3_sampler : register(s8, space0);
Texture2D<float4> mxc_texture_4 : register(t9, space0);
SamplerState _mxc_texture_4_sampler : register(s9, space0);
Texture2D<float4> mxc_texture_5 : register(t10, space0);
SamplerState _mxc_texture_5_sampler : register(s10, space0);
Texture2D<float4> mxc_env_radiance : register(t0, space1);
SamplerState _mxc_env_radiance_sampler : register(s0, space1);

static float4 gl_FragCoord;
static bool gl_FrontFacing;
static float3 vPosition;
static float3 vObjectPosition;
static float3 vNormal;
static float4 vTangent;
static float3 vObjectNormal;
static float3 vObjectTangent;
static float2 vUv;
static float4 outColor;

struct SPIRV_Cross_Input
{
    float3 vPosition : TEXCOORD0;
    float3 vNormal : TEXCOORD1;
    float4 vTangent : TEXCOORD2;
    float2 vUv : TEXCOORD3;
    float3 vObjectPosition : TEXCOORD4;
    float3 vObjectNormal : TEXCOORD5;
    float3 vObjectTangent : TEXCOORD6;
    float4 gl_FragCoord : SV_Position;
    bool gl_FrontFacing : SV_IsFrontFace;
};

struct SPIRV_Cross_Output
{
    float4 outColor : SV_Target0;
};

static float mxc_texture_footprint;

float mod(float x, float y)
{
    return x - y * floor(x / y);
}

float2 mod(float2 x, float2 y)
{
    return x - y * floor(x / y);
}

float3 mod(float3 x, float3 y)
{
    return x - y * floor(x / y);
}

float4 mod(float4 x, float4 y)
{
    return x - y * floor(x / y);
}

uint2 spvTextureSize(Texture2D<float4> Tex, uint Level, out uint Param)
{
    uint2 ret;
    Tex.GetDimensions(Level, ret.x, ret.y, Param);
    return ret;
}

float3 mxc_safe_normalize(float3 v, float3 fallback)
{
    float l2 = dot(v, v);
    float3 _993;
    if (l2 > 9.9999996826552253889678874634872e-21f)
    {
        _993 = v * rsqrt(l2);
    }
    else
    {
        _993 = fallback;
    }
    return _993;
}

float3x3 mxc_frame(float3 N, float3 T)
{
    float3 t = T - (N * dot(N, T));
    float l2 = dot(t, t);
    if (!(l2 > 9.9999999600419720025001879548654e-13f))
    {
        float s = (N.z >= 0.0f) ? 1.0f : (-1.0f);
        float a = (-1.0f) / (s + N.z);
        float b = (N.x * N.y) * a;
        t = float3(1.0f + (((s * N.x) * N.x) * a), s * b, (-s) * N.x);
    }
    else
    {
        t *= rsqrt(l2);
    }
    return float3x3(float3(t), float3(cross(N, t)), float3(N));
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
        return (x >= 0.0f) && (x <= 1.0f);
    }
    if (mode == 1)
    {
        x = clamp(x, 0.0f, 1.0f);
    }
    else
    {
        if (mode == 2)
        {
            x = frac(x);
        }
        else
        {
            x = 1.0f - abs(mod(x, 2.0f) - 1.0f);
        }
    }
    return true;
}

float4 mxc_sample_image(Texture2D<float4> image, SamplerState _image_sampler, float2 uv, float4 fallback, int uaddress, int vaddress, int filtertype, bool missing)
{
    float2 dx = ddx(uv) * float2(mxc_texture_footprint, -mxc_texture_footprint);
    float2 dy = ddy(uv) * float2(mxc_texture_footprint, -mxc_texture_footprint);
    float2 st = uv;
    if (missing)
    {
        return fallback;
    }
    float param = st.x;
    int param_1 = uaddress;
    bool _1655 = mxc_address(param, param_1);
    st.x = param;
    bool _1658 = !_1655;
    bool _1669;
    if (!_1658)
    {
        float param_2 = st.y;
        int param_3 = vaddress;
        bool _1665 = mxc_address(param_2, param_3);
        st.y = param_2;
        _1669 = !_1665;
    }
    else
    {
        _1669 = _1658;
    }
    if (_1669)
    {
        return fallback;
    }
    st.y = 1.0f - st.y;
    if (filtertype == 1)
    {
        uint _1683_dummy_parameter;
        float2 size = float2(int2(spvTextureSize(image, uint(0), _1683_dummy_parameter)));
        return image.SampleLevel(_image_sampler, (min(floor(st * size), size - 1.0f.xx) + 0.5f.xx) / size, 0.0f);
    }
    return image.SampleGrad(_image_sampler, st, dx, dy);
}

float3 mxc_hsv_to_rgb(float3 hsv)
{
    float3 k = clamp(abs((frac(hsv.x.xxx + float3(0.0f, 0.666666686534881591796875f, 0.3333333432674407958984375f)) * 6.0f) - 3.0f.xxx) - 1.0f.xxx, 0.0f.xxx, 1.0f.xxx);
    return lerp(1.0f.xxx, k, hsv.y.xxx) * hsv.z;
}

float3 mxc_normalmap(float3 sampleValue, float2 scale, float3 N, float3 T, float3 B)
{
    float3 v = (sampleValue * 2.0f) - 1.0f.xxx;
    float3 _1561 = v;
    float2 _1563 = _1561.xy * scale;
    v.x = _1563.x;
    v.y = _1563.y;
    float3 param = ((T * v.x) + (B * v.y)) + (N * v.z);
    float3 param_1 = N;
    return mxc_safe_normalize(param, param_1);
}

float3 mxc_to_local(float3x3 frame, float3 v)
{
    return float3(dot(v, frame[0]), dot(v, frame[1]), dot(v, frame[2]));
}

bool mxc_is_delta(float2 alpha)
{
    return max(alpha.x, alpha.y) < 9.9999997473787516355514526367188e-05f;
}

bool mxc_index_matched(MxcLobe l)
{
    return abs(l.eta - 1.0f) < 9.9999997473787516355514526367188e-05f;
}

bool mxc_dielectric_walk_split(MxcLobe l, float3 wo)
{
    bool _2199 = wo.z <= 0.0f;
    bool _2206;
    if (!_2199)
    {
        _2206 = l.eta < 1.0f;
    }
    else
    {
        _2206 = _2199;
    }
    if (_2206)
    {
        return false;
    }
    return true;
}

float4 mxc_table_at(float mu, float x, float firstRow)
{
    float2 t = (float2(sqrt(clamp(mu, 0.0f, 1.0f)), clamp(x, 0.0f, 1.0f)) * 31.0f) + 0.5f.xx;
    return mxc_tables.SampleLevel(_mxc_tables_sampler, float2(t.x / 32.0f, (firstRow + t.y) / 2070.0f), 0.0f);
}

float4 mxc_dielectric_table(float mu, float alpha, float e)
{
    float s = sqrt(clamp(0.5f * (e - 1.0f), 0.0f, 1.0f)) * 31.0f;
    float s0 = min(floor(s), 30.0f);
    float x = sqrt(max(alpha, 0.0f));
    float param = mu;
    float param_1 = x;
    float param_2 = 32.0f * (1.0f + s0);
    float4 a = mxc_table_at(param, param_1, param_2);
    float param_3 = mu;
    float param_4 = x;
    float param_5 = 32.0f * (2.0f + s0);
    float4 b = mxc_table_at(param_3, param_4, param_5);
    return lerp(a, b, (s - s0).xxxx);
}

float mxc_dielectric_albedo(float mu, float alpha, float eta)
{
    float _1808;
    if (eta >= 1.0f)
    {
        _1808 = eta;
    }
    else
    {
        _1808 = 1.0f / max(eta, 0.001000000047497451305389404296875f);
    }
    float e = _1808;
    float param = mu;
    float param_1 = alpha;
    float param_2 = e;
    return mxc_dielectric_table(param, param_1, param_2).x;
}

float mxc_walk_eta_index(float eta)
{
    float e = max(eta, 1.0f);
    return clamp((2.0f * (e - 1.0f)) / (e + 1.0f), 0.0f, 1.0f) * 12.0f;
}

float mxc_walk_texel(float column, float row)
{
    float2 t = float2(column + 0.5f, row + 0.5f) / float2(32.0f, 2070.0f);
    return mxc_tables.SampleLevel(_mxc_tables_sampler, t, 0.0f).x;
}

float mxc_walk_reflectance(float mu, float alpha, float eta)
{
    float param = eta;
    float fe = mxc_walk_eta_index(param);
    float e0 = min(floor(fe), 11.0f);
    float column = sqrt(clamp(mu, 0.0f, 1.0f)) * 31.0f;
    float row = 1654.0f + (sqrt(clamp(alpha, 0.0f, 1.0f)) * 31.0f);
    float param_1 = column;
    float param_2 = row + (e0 * 32.0f);
    float a = mxc_walk_texel(param_1, param_2);
    float param_3 = column;
    float param_4 = row + ((e0 + 1.0f) * 32.0f);
    float b = mxc_walk_texel(param_3, param_4);
    return lerp(a, b, fe - e0);
}

float mxc_lobe_eta(MxcLobe l, bool above)
{
    float _1936;
    if (above)
    {
        _1936 = l.eta;
    }
    else
    {
        _1936 = 1.0f / l.eta;
    }
    return _1936;
}

float mxc_dielectric_albedo_rt(float mu, float alpha, float eta)
{
    if (eta >= 1.0f)
    {
        float param = mu;
        float param_1 = alpha;
        float param_2 = eta;
        return mxc_dielectric_table(param, param_1, param_2).y;
    }
    float param_3 = mu;
    float param_4 = alpha;
    float param_5 = 1.0f / max(eta, 0.001000000047497451305389404296875f);
    return mxc_dielectric_table(param_3, param_4, param_5).z;
}

float4 mxc_table(float mu, float x)
{
    float param = mu;
    float param_1 = x;
    float param_2 = 0.0f;
    return mxc_table_at(param, param_1, param_2);
}

float2 mxc_split_sum(float mu, float alpha)
{
    float param = mu;
    float param_1 = sqrt(max(alpha, 0.0f));
    return mxc_table(param, param_1).xy;
}

float mxc_lobe_cosine_below_coat(MxcLobe l, float mu)
{
    bool _1961 = l.kind == 1;
    bool _1967;
    if (_1961)
    {
        _1967 = l.etaAbove > 1.0f;
    }
    else
    {
        _1967 = _1961;
    }
    if (_1967)
    {
        return sqrt(1.0f - ((1.0f - (mu * mu)) / (l.etaAbove * l.etaAbove)));
    }
    return mu;
}

float mxc_fresnel_dielectric(float cosi, float eta)
{
    if (abs(eta - 1.0f) < 9.9999999747524270787835121154785e-07f)
    {
        return 0.0f;
    }
    float sin2t = (1.0f - (cosi * cosi)) / (eta * eta);
    if (sin2t >= 1.0f)
    {
        return 1.0f;
    }
    float cost = sqrt(1.0f - sin2t);
    float rs = (cosi - (eta * cost)) / (cosi + (eta * cost));
    float rp = ((eta * cosi) - cost) / ((eta * cosi) + cost);
    return 0.5f * ((rs * rs) + (rp * rp));
}

float3 mxc_lobe_fresnel(MxcLobe l, inout float _cosh, bool above)
{
    float3 f = 1.0f.xxx;
    if (above)
    {
        MxcLobe param = l;
        float param_1 = clamp(_cosh, 0.0f, 1.0f);
        _cosh = mxc_lobe_cosine_below_coat(param, param_1);
    }
    if (l.kind == 1)
    {
        MxcLobe param_2 = l;
        bool param_3 = above;
        float param_4 = _cosh;
        float param_5 = mxc_lobe_eta(param_2, param_3);
        f = mxc_fresnel_dielectric(param_4, param_5).xxx;
    }
    return f;
}

float3 mxc_lobe_ms_scale(MxcLobe l, float3 wo)
{
    bool _2330 = l.kind == 1;
    bool _2337;
    if (!_2330)
    {
        _2337 = l.kind == 2;
    }
    else
    {
        _2337 = _2330;
    }
    bool _2344;
    if (!_2337)
    {
        _2344 = l.kind == 3;
    }
    else
    {
        _2344 = _2337;
    }
    bool microfacet = _2344;
    bool _2346 = !microfacet;
    bool _2353;
    if (!_2346)
    {
        float2 param = l.alpha;
        _2353 = mxc_is_delta(param);
    }
    else
    {
        _2353 = _2346;
    }
    if (_2353)
    {
        return 1.0f.xxx;
    }
    float alpha = sqrt(l.alpha.x * l.alpha.y);
    bool _2364 = l.kind == 1;
    bool _2369;
    if (_2364)
    {
        MxcLobe param_1 = l;
        _2369 = mxc_index_matched(param_1);
    }
    else
    {
        _2369 = _2364;
    }
    if (_2369)
    {
        return 1.0f.xxx;
    }
    bool _2374 = l.kind == 1;
    bool _2381;
    if (_2374)
    {
        _2381 = (l.mode & 4) == 0;
    }
    else
    {
        _2381 = _2374;
    }
    if (_2381)
    {
        MxcLobe param_2 = l;
        float3 param_3 = wo;
        if (mxc_dielectric_walk_split(param_2, param_3))
        {
            float param_4 = wo.z;
            float param_5 = alpha;
            float param_6 = l.eta;
            float rss = mxc_dielectric_albedo(param_4, param_5, param_6);
            float param_7 = wo.z;
            float param_8 = alpha;
            float param_9 = l.eta;
            return clamp(mxc_walk_reflectance(param_7, param_8, param_9) / max(rss, 9.9999997473787516355514526367188e-05f), 1.0f, 20.0f).xxx;
        }
        MxcLobe param_10 = l;
        bool param_11 = wo.z >= 0.0f;
        float param_12 = abs(wo.z);
        float param_13 = alpha;
        float param_14 = mxc_lobe_eta(param_10, param_11);
        float e = mxc_dielectric_albedo_rt(param_12, param_13, param_14);
        float3 k = (1.0f / max(e, 0.0500000007450580596923828125f)).xxx;
        return k;
    }
    float param_15 = max(wo.z, 0.0f);
    float param_16 = alpha;
    float2 ab = mxc_split_sum(param_15, param_16);
    float e_1 = ab.x + ab.y;
    MxcLobe param_17 = l;
    float param_18 = 1.0f;
    bool param_19 = true;
    float3 _2432 = mxc_lobe_fresnel(param_17, param_18, param_19);
    return 1.0f.xxx + ((_2432 * (1.0f - e_1)) / max(e_1, 0.0500000007450580596923828125f).xxx);
}

float mxc_safe_sqrt(float x)
{
    return sqrt(max(x, 0.0f));
}

float mxc_fon_albedo(float sigma, float mu)
{
    float a = 1.0f / (1.0f + (0.2877933979034423828125f * sigma));
    float c = clamp(mu, 0.0f, 1.0f);
    float param = 1.0f - (c * c);
    float s = mxc_safe_sqrt(param);
    float theta = acos(c);
    float _2139;
    if (c > 9.9999997473787516355514526367188e-05f)
    {
        _2139 = (1.0f - ((s * s) * s)) / c;
    }
    else
    {
        _2139 = 1.5f * c;
    }
    float tail = _2139;
    float g = ((s * (theta - (s * c))) + ((0.666666686534881591796875f * s) * tail)) - (0.666666686534881591796875f * s);
    return a + (((sigma * a) * g) * 0.3183098733425140380859375f);
}

float3 mxc_lobe_albedo_scaled(MxcLobe l, float3 wo, float3 ms)
{
    float mu = clamp(wo.z, 0.0f, 1.0f);
    bool _2577 = l.kind == 1;
    bool _2584;
    if (!_2577)
    {
        _2584 = l.kind == 2;
    }
    else
    {
        _2584 = _2577;
    }
    bool _2591;
    if (!_2584)
    {
        _2591 = l.kind == 3;
    }
    else
    {
        _2591 = _2584;
    }
    if (_2591)
    {
        float alpha = sqrt(l.alpha.x * l.alpha.y);
        bool _2602 = l.kind == 1;
        bool _2609;
        if (_2602)
        {
            float2 param = l.alpha;
            _2609 = !mxc_is_delta(param);
        }
        else
        {
            _2609 = _2602;
        }
        if (_2609)
        {
            MxcLobe param_1 = l;
            float param_2 = mu;
            float param_3 = mxc_lobe_cosine_below_coat(param_1, param_2);
            float param_4 = alpha;
            float param_5 = l.eta;
            float3 e = mxc_dielectric_albedo(param_3, param_4, param_5).xxx;
            return clamp((e * l.c0) * ms, 0.0f.xxx, 1.0f.xxx);
        }
        float param_6 = mu;
        float param_7 = alpha;
        float2 ab = mxc_split_sum(param_6, param_7);
        MxcLobe param_8 = l;
        float param_9 = 1.0f;
        bool param_10 = true;
        float3 _2633 = mxc_lobe_fresnel(param_8, param_9, param_10);
        float3 f0 = _2633;
        MxcLobe param_11 = l;
        float param_12 = 0.0f;
        bool param_13 = true;
        float3 _2635 = mxc_lobe_fresnel(param_11, param_12, param_13);
        float3 f90 = _2635;
        float3 _2565;
        if (l.kind == 1)
        {
            _2565 = l.c0;
        }
        else
        {
            _2565 = 1.0f.xxx;
        }
        float3 tint = _2565;
        float2 param_14 = l.alpha;
        if (mxc_is_delta(param_14))
        {
            MxcLobe param_15 = l;
            float param_16 = mu;
            bool param_17 = true;
            float3 _2652 = mxc_lobe_fresnel(param_15, param_16, param_17);
            return _2652 * tint;
        }
        return clamp((((f0 * ab.x) + (f90 * ab.y)) * tint) * ms, 0.0f.xxx, 1.0f.xxx);
    }
    if (l.kind == 4)
    {
        float param_18 = l.p0;
        float param_19 = mu;
        return l.c0 * mxc_fon_albedo(param_18, param_19);
    }
    if (l.kind == 8)
    {
        return l.c0;
    }
    return l.c0;
}

float3 mxc_lobe_albedo(MxcLobe l, float3 wo)
{
    MxcLobe param = l;
    float3 param_1 = wo;
    MxcLobe param_2 = l;
    float3 param_3 = wo;
    float3 param_4 = mxc_lobe_ms_scale(param, param_1);
    return mxc_lobe_albedo_scaled(param_2, param_3, param_4);
}

float3 mxc_lobe_layer_albedo(MxcLobe l, float3 wo)
{
    bool _2718 = l.kind == 9;
    bool _2725;
    if (!_2718)
    {
        _2725 = l.kind == 10;
    }
    else
    {
        _2725 = _2718;
    }
    if (_2725)
    {
        MxcLobe white = l;
        white.c0 = 1.0f.xxx;
        MxcLobe param = white;
        float3 param_1 = wo;
        return mxc_lobe_albedo(param, param_1);
    }
    MxcLobe param_2 = l;
    float3 param_3 = wo;
    return mxc_lobe_albedo(param_2, param_3);
}

float mxc_lobe_ms_transmit(MxcLobe l, float3 wo, float3 ms)
{
    bool _2232 = l.kind != 1;
    bool _2239;
    if (!_2232)
    {
        float2 param = l.alpha;
        _2239 = mxc_is_delta(param);
    }
    else
    {
        _2239 = _2232;
    }
    bool _2245;
    if (!_2239)
    {
        MxcLobe param_1 = l;
        _2245 = mxc_index_matched(param_1);
    }
    else
    {
        _2245 = _2239;
    }
    bool _2253;
    if (!_2245)
    {
        _2253 = (l.mode & 4) != 0;
    }
    else
    {
        _2253 = _2245;
    }
    bool _2261;
    if (!_2253)
    {
        MxcLobe param_2 = l;
        float3 param_3 = wo;
        _2261 = !mxc_dielectric_walk_split(param_2, param_3);
    }
    else
    {
        _2261 = _2253;
    }
    if (_2261)
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
    return clamp((1.0f - mxc_walk_reflectance(param_10, param_11, param_12)) / max(tss, 0.0500000007450580596923828125f), 1.0f, 20.0f);
}

float mxc_luminance(float3 c)
{
    return dot(c, float3(0.2125999927520751953125f, 0.715200006961822509765625f, 0.072200000286102294921875f));
}

float mxc_lobe_choice(MxcLobe l, float3 woLocal, float3 ms)
{
    if (all(bool3(l.weight.x == 0.0f.xxx.x, l.weight.y == 0.0f.xxx.y, l.weight.z == 0.0f.xxx.z)))
    {
        return 0.0f;
    }
    MxcLobe param = l;
    float3 param_1 = woLocal;
    float3 param_2 = ms;
    float3 param_3 = l.weight * mxc_lobe_albedo_scaled(param, param_1, param_2);
    return max(mxc_luminance(param_3), 0.0f) + 9.9999997473787516355514526367188e-05f;
}

bool mxc_lobe_ms_shaped(MxcLobe l, float3 wo)
{
    bool _2452 = wo.z <= 0.0f;
    bool _2459;
    if (!_2452)
    {
        float2 param = l.alpha;
        _2459 = mxc_is_delta(param);
    }
    else
    {
        _2459 = _2452;
    }
    if (_2459)
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
    bool _2478 = l.kind == 1;
    bool _2485;
    if (_2478)
    {
        _2485 = (l.mode & 1) != 0;
    }
    else
    {
        _2485 = _2478;
    }
    bool _2492;
    if (_2485)
    {
        _2492 = (l.mode & 4) == 0;
    }
    else
    {
        _2492 = _2485;
    }
    bool _2498;
    if (_2492)
    {
        MxcLobe param_1 = l;
        _2498 = !mxc_index_matched(param_1);
    }
    else
    {
        _2498 = _2492;
    }
    bool _2504;
    if (_2498)
    {
        MxcLobe param_2 = l;
        float3 param_3 = wo;
        _2504 = mxc_dielectric_walk_split(param_2, param_3);
    }
    else
    {
        _2504 = _2498;
    }
    return _2504;
}

bool mxc_lobe_transmits(MxcLobe l)
{
    return false;
}

MxcLobe mxc_ms_lobe(MxcLobe l, bool transmitted)
{
    MxcLobe m = l;
    m.alpha = min(l.alpha * (transmitted ? 3.0f : 1.5f), 1.0f.xx);
    int _2510;
    if (transmitted)
    {
        _2510 = l.mode & (-2);
    }
    else
    {
        _2510 = l.mode & (-3);
    }
    m.mode = _2510;
    if (l.kind == 1)
    {
        m.c0 = 1.0f.xxx;
        m.c1 = 1.0f.xxx;
    }
    return m;
}

void mxc_closure_prepare(inout MxcClosure c, float3 wo)
{
    c.choiceTotal = 0.0f;
    float _3286;
    for (int k = 0; k < c.count; k++)
    {
        MxcLobe l = c.lobes[k];
        c.ms[k] = 1.0f.xxx;
        c.msT[k] = 1.0f;
        c.msLobe[k] = 0.0f.xxx;
        c.msLobeT[k] = 0.0f.xxx;
        c.msPick[k] = 0.0f;
        c.msSplit[k] = 1.0f;
        c.choice[k] = 0.0f;
        if (all(bool3(l.weight.x == 0.0f.xxx.x, l.weight.y == 0.0f.xxx.y, l.weight.z == 0.0f.xxx.z)))
        {
            continue;
        }
        float3 param = l.N;
        float3 param_1 = l.T;
        float3x3 param_2 = mxc_frame(param, param_1);
        float3 param_3 = wo;
        float3 o = mxc_to_local(param_2, param_3);
        MxcLobe param_4 = l;
        float3 param_5 = o;
        float3 ms = mxc_lobe_ms_scale(param_4, param_5);
        MxcLobe param_6 = l;
        float3 param_7 = o;
        float3 param_8 = ms;
        c.msT[k] = mxc_lobe_ms_transmit(param_6, param_7, param_8);
        MxcLobe param_9 = l;
        float3 param_10 = o;
        float3 param_11 = ms;
        c.choice[k] = mxc_lobe_choice(param_9, param_10, param_11);
        c.choiceTotal += c.choice[k];
        MxcLobe param_12 = l;
        float3 param_13 = o;
        if (mxc_lobe_ms_shaped(param_12, param_13))
        {
            float alpha = sqrt(l.alpha.x * l.alpha.y);
            MxcLobe param_14 = l;
            float3 param_15 = o;
            float3 param_16 = 1.0f.xxx;
            float3 reflected = mxc_lobe_albedo_scaled(param_14, param_15, param_16);
            MxcLobe param_17 = l;
            float3 param_18 = o;
            float3 param_19 = ms;
            float3 addedR = max(mxc_lobe_albedo_scaled(param_17, param_18, param_19) - reflected, 0.0f.xxx);
            float3 transmitted = 0.0f.xxx;
            float3 addedT = 0.0f.xxx;
            bool _3374 = l.kind == 1;
            bool _3379;
            if (_3374)
            {
                MxcLobe param_20 = l;
                _3379 = mxc_lobe_transmits(param_20);
            }
            else
            {
                _3379 = _3374;
            }
            if (_3379)
            {
                float param_21 = o.z;
                float param_22 = alpha;
                float param_23 = l.eta;
                float rss = mxc_dielectric_albedo(param_21, param_22, param_23);
                float param_24 = o.z;
                float param_25 = alpha;
                float param_26 = l.eta;
                transmitted = l.c1 * max(mxc_dielectric_albedo_rt(param_24, param_25, param_26) - rss, 0.0f);
                addedT = transmitted * max(c.msT[k] - 1.0f, 0.0f);
            }
            MxcLobe param_27 = l;
            bool param_28 = false;
            MxcLobe mr = mxc_ms_lobe(param_27, param_28);
            MxcLobe param_29 = mr;
            float3 param_30 = o;
            float3 param_31 = 1.0f.xxx;
            float3 broadR = mxc_lobe_albedo_scaled(param_29, param_30, param_31);
            float broadT = 1.0f;
            bool _3414 = l.kind == 1;
            bool _3419;
            if (_3414)
            {
                MxcLobe param_32 = l;
                _3419 = mxc_lobe_transmits(param_32);
            }
            else
            {
                _3419 = _3414;
            }
            if (_3419)
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
            c.msLobe[k] = addedR / max(broadR, 9.9999997473787516355514526367188e-05f.xxx);
            c.msLobeT[k] = addedT / max(broadT, 9.9999997473787516355514526367188e-05f).xxx;
            float3 param_41 = ((reflected + addedR) + transmitted) + addedT;
            float total = max(mxc_luminance(param_41), 9.9999999747524270787835121154785e-07f);
            float3 param_42 = addedR + addedT;
            float added = mxc_luminance(param_42);
            c.msPick[k] = 0.999000012874603271484375f * min(added / total, 1.0f);
            if (added > 0.0f)
            {
                float3 param_43 = addedR;
                _3286 = mxc_luminance(param_43) / added;
            }
            else
            {
                _3286 = 1.0f;
            }
            c.msSplit[k] = _3286;
            c.msT[k] = 1.0f;
        }
        else
        {
            c.ms[k] = ms;
        }
    }
}

void mxc_material_closure(MxcGeometry g, float3 wo, inout MxcClosure c)
{
    float2 v3 = g.uv;
    float2 v4 = v3 * 3.0f.xx;
    float2 param = v4;
    float4 param_1 = 0.0f.xxxx;
    int param_2 = 2;
    int param_3 = 2;
    int param_4 = 0;
    bool param_5 = (mxc_params.Load(0) & 1u) != 0u;
    float v8 = mxc_sample_image(mxc_texture_0, _mxc_texture_0_sampler, param, param_1, param_2, param_3, param_4, param_5).x;
    float v10 = max(v8, 9.9999997473787516355514526367188e-06f);
    float v11 = 0.852999985218048095703125f / v10;
    float2 param_6 = v4;
    float4 param_7 = 0.0f.xxxx;
    int param_8 = 2;
    int param_9 = 2;
    int param_10 = 0;
    bool param_11 = (mxc_params.Load(0) & 2u) != 0u;
    float v13 = mxc_sample_image(mxc_texture_1, _mxc_texture_1_sampler, param_6, param_7, param_8, param_9, param_10, param_11).x;
    float v14 = v11 * v13;
    float2 param_12 = v4;
    float4 param_13 = 0.0f.xxxx;
    int param_14 = 2;
    int param_15 = 2;
    int param_16 = 0;
    bool param_17 = (mxc_params.Load(0) & 4u) != 0u;
    float v20 = mxc_sample_image(mxc_texture_2, _mxc_texture_2_sampler, param_12, param_13, param_14, param_15, param_16, param_17).x;
    float v21 = 0.2479999959468841552734375f * v20;
    float2 param_18 = v4;
    float4 param_19 = 0.0f.xxxx;
    int param_20 = 2;
    int param_21 = 2;
    int param_22 = 0;
    bool param_23 = (mxc_params.Load(0) & 8u) != 0u;
    float v25 = mxc_sample_image(mxc_texture_3, _mxc_texture_3_sampler, param_18, param_19, param_20, param_21, param_22, param_23).x;
    float v26 = 0.082999996840953826904296875f * v25;
    float2 param_24 = v4;
    float4 param_25 = 0.0f.xxxx;
    int param_26 = 2;
    int param_27 = 2;
    int param_28 = 0;
    bool param_29 = (mxc_params.Load(0) & 16u) != 0u;
    float v28 = mxc_sample_image(mxc_texture_4, _mxc_texture_4_sampler, param_24, param_25, param_26, param_27, param_28, param_29).x;
    float v29 = v26 + v28;
    float v31 = v29 - 0.3499999940395355224609375f;
    float v32 = v31 * 0.082999996840953826904296875f;
    float v34 = 0.787000000476837158203125f * v25;
    float v35 = v29 * v34;
    float3 v36 = float3(v32, 0.0f, v35);
    float3 v38 = v36 + float3(0.0480653941631317138671875f, 1.0f, 0.661876022815704345703125f);
    float3 param_30 = v38;
    float3 v39 = mxc_hsv_to_rgb(param_30);
    float3 v40 = lerp(v39, 0.5637199878692626953125f.xxx, v21.xxx);
    float3 v41 = v40 * v28;
    float3 v43 = 0.2632730007171630859375f.xxx * v28;
    float3 v44 = lerp(v43, v41, v8.xxx);
    float3 v45 = clamp(v44, 0.0f.xxx, 1.0f.xxx);
    float3 v46 = clamp(v45, 0.0f.xxx, 1.0f.xxx);
    float2 param_31 = v4;
    float4 param_32 = float4(0.0f, 0.0f, 0.0f, 1.0f);
    int param_33 = 2;
    int param_34 = 2;
    int param_35 = 0;
    bool param_36 = (mxc_params.Load(0) & 32u) != 0u;
    float3 v48 = mxc_sample_image(mxc_texture_5, _mxc_texture_5_sampler, param_31, param_32, param_33, param_34, param_35, param_36).xyz;
    float3 v49 = g.N;
    float3 v50 = g.T;
    float3 v51 = g.B;
    float3 param_37 = v48;
    float2 param_38 = 1.0f.xx;
    float3 param_39 = v49;
    float3 param_40 = v50;
    float3 param_41 = v51;
    float3 v52 = mxc_normalmap(param_37, param_38, param_39, param_40, param_41);
    float v55 = v14 * v14;
    float v56 = clamp(v55, 1.0000000116860974230803549289703e-07f, 1.0f);
    float2 v57 = float2(v56, v56);
    c.emission = 0.0f.xxx;
    c.transparency = 0.0f.xxx;
    MxcLobe lobe0;
    lobe0.kind = 1;
    lobe0.mode = 1;
    float3 param_42 = v52;
    float3 param_43 = g.N;
    lobe0.N = mxc_safe_normalize(param_42, param_43);
    lobe0.T = v50;
    lobe0.alpha = v57;
    lobe0.eta = 1.5f;
    lobe0.etaAbove = 1.0f;
    lobe0.c0 = 1.0f.xxx;
    lobe0.c1 = 1.0f.xxx;
    lobe0.c2 = 1.0f.xxx;
    lobe0.p0 = 0.0f;
    lobe0.p1 = 1.0f;
    lobe0.film = 0.0f.xxx;
    lobe0.tau = 0.0f.xxx;
    lobe0.tauEta = 1.0f;
    float3 param_44 = lobe0.N;
    float3 param_45 = lobe0.T;
    float3x3 param_46 = mxc_frame(param_44, param_45);
    float3 param_47 = wo;
    MxcLobe param_48 = lobe0;
    float3 param_49 = mxc_to_local(param_46, param_47);
    float3 e1 = mxc_lobe_layer_albedo(param_48, param_49);
    float3 w2 = 1.0f.xxx - e1;
    MxcLobe lobe3;
    lobe3.kind = 4;
    lobe3.mode = 1;
    float3 param_50 = v52;
    float3 param_51 = g.N;
    lobe3.N = mxc_safe_normalize(param_50, param_51);
    lobe3.T = g.T;
    lobe3.alpha = 0.0f.xx;
    lobe3.eta = 1.5f;
    lobe3.etaAbove = 1.0f;
    lobe3.c0 = v46;
    lobe3.c1 = 1.0f.xxx;
    lobe3.c2 = 1.0f.xxx;
    lobe3.p0 = 0.0f;
    lobe3.p1 = 1.0f;
    lobe3.film = 0.0f.xxx;
    lobe3.tau = 0.0f.xxx;
    lobe3.tauEta = 1.0f;
    lobe0.weight = 1.0f.xxx;
    c.lobes[0] = lobe0;
    lobe3.weight = w2;
    c.lobes[1] = lobe3;
    c.count = 2;
    MxcClosure param_52 = c;
    float3 param_53 = wo;
    mxc_closure_prepare(param_52, param_53);
    c = param_52;
}

int mxc_light_count()
{
    int _4530;
    if (_254)
    {
        _4530 = MXC_LIGHT_COUNT;
    }
    else
    {
        _4530 = mxc_view_counts.x;
    }
    return min(_4530, 8);
}

int mxc_light_kinds()
{
    return _257;
}

int mxc_environment_code()
{
    int _4522;
    if (_252)
    {
        _4522 = MXC_ENVIRONMENT;
    }
    else
    {
        _4522 = mxc_view_counts.y;
    }
    return _4522;
}

float mxc_uniform(inout uint seed)
{
    uint param = seed;
    seed = mxc_pcg(param);
    return float(seed >> uint(8)) * 5.9604644775390625e-08f;
}

float mxc_radical_inverse(inout uint i, uint base)
{
    if (base == 2u)
    {
        return float(reversebits(i) >> uint(8)) * 5.9604644775390625e-08f;
    }
    float inv = 1.0f / float(base);
    float f = inv;
    float r = 0.0f;
    for (; i > 0u; i /= base)
    {
        r += (f * float(i % base));
        f *= inv;
    }
    return min(r, 0.999999940395355224609375f);
}

float3 mxc_sample_cosine(float2 u)
{
    float r = sqrt(u.x);
    float phi = 6.283185482025146484375f * u.y;
    float param = 1.0f - u.x;
    return float3(r * cos(phi), r * sin(phi), mxc_safe_sqrt(param));
}

float2 mxc_rough_alpha(float2 alpha)
{
    return max(alpha, 9.9999997473787516355514526367188e-05f.xx);
}

float mxc_ggx_d(float3 m, inout float2 alpha)
{
    if (m.z <= 0.0f)
    {
        return 0.0f;
    }
    float2 param = alpha;
    alpha = mxc_rough_alpha(param);
    float3 s = float3(m.x / alpha.x, m.y / alpha.y, m.z);
    float d = dot(s, s);
    return 1.0f / ((((3.1415927410125732421875f * alpha.x) * alpha.y) * d) * d);
}

float mxc_sqr(float x)
{
    return x * x;
}

float mxc_ggx_lambda(float3 v, inout float2 alpha)
{
    float2 param = alpha;
    alpha = mxc_rough_alpha(param);
    float z2 = v.z * v.z;
    if (z2 <= 0.0f)
    {
        return 10000000000.0f;
    }
    float param_1 = alpha.x * v.x;
    float param_2 = alpha.y * v.y;
    float a2 = (mxc_sqr(param_1) + mxc_sqr(param_2)) / z2;
    return 0.5f * ((-1.0f) + sqrt(1.0f + a2));
}

float mxc_ggx_g2(float3 wo, float3 wi, float2 alpha)
{
    float3 param = wo;
    float2 param_1 = alpha;
    float _1297 = mxc_ggx_lambda(param, param_1);
    float3 param_2 = wi;
    float2 param_3 = alpha;
    float _1301 = mxc_ggx_lambda(param_2, param_3);
    return 1.0f / ((1.0f + _1297) + _1301);
}

float3 mxc_microfacet_reflect(MxcLobe l, float3 wo, float3 wi)
{
    bool _2032 = wo.z <= 0.0f;
    bool _2039;
    if (!_2032)
    {
        _2039 = wi.z <= 0.0f;
    }
    else
    {
        _2039 = _2032;
    }
    bool _2046;
    if (!_2039)
    {
        float2 param = l.alpha;
        _2046 = mxc_is_delta(param);
    }
    else
    {
        _2046 = _2039;
    }
    if (_2046)
    {
        return 0.0f.xxx;
    }
    float3 h = normalize(wo + wi);
    MxcLobe param_1 = l;
    float param_2 = max(dot(wo, h), 0.0f);
    bool param_3 = true;
    float3 _2058 = mxc_lobe_fresnel(param_1, param_2, param_3);
    float3 f = _2058;
    if (l.kind == 1)
    {
        f *= l.c0;
    }
    float3 param_4 = h;
    float2 param_5 = l.alpha;
    float _2072 = mxc_ggx_d(param_4, param_5);
    float3 param_6 = wo;
    float3 param_7 = wi;
    float2 param_8 = l.alpha;
    return ((f * _2072) * mxc_ggx_g2(param_6, param_7, param_8)) / (4.0f * wo.z).xxx;
}

float mxc_fon(float sigma, float3 wo, float3 wi)
{
    float a = 1.0f / (1.0f + (0.2877933979034423828125f * sigma));
    float s = dot(wi, wo) - (wi.z * wo.z);
    float _2093;
    if (s > 0.0f)
    {
        _2093 = max(max(wi.z, wo.z), 9.9999999747524270787835121154785e-07f);
    }
    else
    {
        _2093 = 1.0f;
    }
    float t = _2093;
    return (a + (((sigma * a) * s) / t)) * 0.3183098733425140380859375f;
}

float3 mxc_lobe_eval(MxcLobe l, float3 wo, float3 wi)
{
    switch (l.kind)
    {
        case 1:
        {
            if ((wo.z * wi.z) > 0.0f)
            {
                if ((l.mode & 1) == 0)
                {
                    return 0.0f.xxx;
                }
                if (wo.z < 0.0f)
                {
                    MxcLobe m = l;
                    m.eta = 1.0f / l.eta;
                    m.c0 = 1.0f.xxx;
                    MxcLobe param = m;
                    float3 param_1 = -wo;
                    float3 param_2 = -wi;
                    return mxc_microfacet_reflect(param, param_1, param_2);
                }
                MxcLobe param_3 = l;
                float3 param_4 = wo;
                float3 param_5 = wi;
                return mxc_microfacet_reflect(param_3, param_4, param_5);
            }
            return 0.0f.xxx;
        }
        case 2:
        case 3:
        {
            bool _2799 = l.kind == 3;
            bool _2806;
            if (_2799)
            {
                _2806 = (l.mode & 1) == 0;
            }
            else
            {
                _2806 = _2799;
            }
            if (_2806)
            {
                return 0.0f.xxx;
            }
            MxcLobe param_6 = l;
            float3 param_7 = wo;
            float3 param_8 = wi;
            return mxc_microfacet_reflect(param_6, param_7, param_8);
        }
        case 4:
        {
            bool _2815 = wo.z > 0.0f;
            bool _2821;
            if (_2815)
            {
                _2821 = wi.z > 0.0f;
            }
            else
            {
                _2821 = _2815;
            }
            float3 _2751;
            if (_2821)
            {
                float param_9 = l.p0;
                float3 param_10 = wo;
                float3 param_11 = wi;
                _2751 = (l.c0 * mxc_fon(param_9, param_10, param_11)) * wi.z;
            }
            else
            {
                _2751 = 0.0f.xxx;
            }
            return _2751;
        }
        default:
        {
            return 0.0f.xxx;
        }
    }
}

float mxc_ggx_g1(float3 v, float2 alpha)
{
    float3 param = v;
    float2 param_1 = alpha;
    float _1283 = mxc_ggx_lambda(param, param_1);
    return 1.0f / (1.0f + _1283);
}

float mxc_ggx_pdf_vndf(float3 wo, float3 m, float2 alpha)
{
    if (wo.z <= 0.0f)
    {
        return 0.0f;
    }
    float3 param = wo;
    float2 param_1 = alpha;
    float3 param_2 = m;
    float2 param_3 = alpha;
    float _1456 = mxc_ggx_d(param_2, param_3);
    return ((mxc_ggx_g1(param, param_1) * max(dot(wo, m), 0.0f)) * _1456) / wo.z;
}

float mxc_mean(float3 c)
{
    return ((c.x + c.y) + c.z) * 0.3333333432674407958984375f;
}

float mxc_lobe_pdf(MxcLobe l, float3 wo, float3 wi)
{
    switch (l.kind)
    {
        case 1:
        case 2:
        case 3:
        {
            float2 param = l.alpha;
            if (mxc_is_delta(param))
            {
                return 0.0f;
            }
            bool above = wo.z > 0.0f;
            float3 _2845;
            if (above)
            {
                _2845 = wo;
            }
            else
            {
                _2845 = -wo;
            }
            float3 o = _2845;
            float3 _2847;
            if (above)
            {
                _2847 = wi;
            }
            else
            {
                _2847 = -wi;
            }
            float3 i = _2847;
            if (i.z > 0.0f)
            {
                float3 h = normalize(o + i);
                float3 param_1 = o;
                float3 param_2 = h;
                float2 param_3 = l.alpha;
                float p = mxc_ggx_pdf_vndf(param_1, param_2, param_3) / (4.0f * max(dot(o, h), 9.9999999747524270787835121154785e-07f));
                if (l.kind == 2)
                {
                    return p;
                }
                if ((l.mode & 1) == 0)
                {
                    return 0.0f;
                }
                MxcLobe param_4 = l;
                float param_5 = max(dot(o, h), 0.0f);
                bool param_6 = above;
                float3 _2943 = mxc_lobe_fresnel(param_4, param_5, param_6);
                float3 param_7 = _2943;
                float fr = mxc_mean(param_7);
                MxcLobe param_8 = l;
                bool _2947 = mxc_lobe_transmits(param_8);
                bool _2954;
                if (_2947)
                {
                    _2954 = (l.mode & 1) != 0;
                }
                else
                {
                    _2954 = _2947;
                }
                return p * (_2954 ? fr : 1.0f);
            }
            return 0.0f;
        }
        default:
        {
            bool _2867 = wo.z > 0.0f;
            bool _2873;
            if (_2867)
            {
                _2873 = wi.z > 0.0f;
            }
            else
            {
                _2873 = _2867;
            }
            float _2859;
            if (_2873)
            {
                _2859 = wi.z * 0.3183098733425140380859375f;
            }
            else
            {
                _2859 = 0.0f;
            }
            return _2859;
        }
    }
}

float3 mxc_ggx_sample_vndf(float3 wo, inout float2 alpha, float2 u)
{
    float2 param = alpha;
    alpha = mxc_rough_alpha(param);
    float3 vh = normalize(float3(alpha.x * wo.x, alpha.y * wo.y, wo.z));
    float lensq = (vh.x * vh.x) + (vh.y * vh.y);
    float3 _1313;
    if (lensq > 0.0f)
    {
        _1313 = float3(-vh.y, vh.x, 0.0f) * rsqrt(lensq);
    }
    else
    {
        _1313 = float3(1.0f, 0.0f, 0.0f);
    }
    float3 t1 = _1313;
    float3 t2 = cross(vh, t1);
    float r = sqrt(u.x);
    float phi = 6.283185482025146484375f * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5f * (1.0f + vh.z);
    float param_1 = 1.0f - (p1 * p1);
    p2 = ((1.0f - s) * mxc_safe_sqrt(param_1)) + (s * p2);
    float param_2 = (1.0f - (p1 * p1)) - (p2 * p2);
    float3 nh = ((t1 * p1) + (t2 * p2)) + (vh * mxc_safe_sqrt(param_2));
    return normalize(float3(alpha.x * nh.x, alpha.y * nh.y, max(nh.z, 0.0f)));
}

MxcLobeSample mxc_lobe_sample(MxcLobe l, float3 wo, float3 u)
{
    MxcLobeSample s;
    s.valid = false;
    s.delta = false;
    s.pdf = 0.0f;
    s.value = 0.0f.xxx;
    s.wi = float3(0.0f, 0.0f, 1.0f);
    switch (l.kind)
    {
        case 1:
        case 2:
        case 3:
        {
            bool above = wo.z > 0.0f;
            float3 _2966;
            if (above)
            {
                _2966 = wo;
            }
            else
            {
                _2966 = -wo;
            }
            float3 o = _2966;
            if (o.z <= 0.0f)
            {
                return s;
            }
            float2 param = l.alpha;
            bool delta = mxc_is_delta(param);
            float3 _2970;
            if (delta)
            {
                _2970 = float3(0.0f, 0.0f, 1.0f);
            }
            else
            {
                float3 param_1 = o;
                float2 param_2 = l.alpha;
                float2 param_3 = u.xy;
                float3 _3071 = mxc_ggx_sample_vndf(param_1, param_2, param_3);
                _2970 = _3071;
            }
            float3 m = _2970;
            float hm = dot(o, m);
            bool _3078 = l.kind == 1;
            bool _3085;
            if (!_3078)
            {
                _3085 = l.kind == 3;
            }
            else
            {
                _3085 = _3078;
            }
            bool _3090;
            if (_3085)
            {
                MxcLobe param_4 = l;
                _3090 = mxc_lobe_transmits(param_4);
            }
            else
            {
                _3090 = _3085;
            }
            bool transmits = _3090;
            bool _3093 = l.kind == 2;
            bool _3101;
            if (!_3093)
            {
                _3101 = (l.mode & 1) != 0;
            }
            else
            {
                _3101 = _3093;
            }
            bool reflects = _3101;
            MxcLobe param_5 = l;
            float param_6 = max(hm, 0.0f);
            bool param_7 = above;
            float3 _3106 = mxc_lobe_fresnel(param_5, param_6, param_7);
            float3 f = _3106;
            float _2983;
            if (transmits)
            {
                float3 param_8 = f;
                _2983 = mxc_mean(param_8);
            }
            else
            {
                _2983 = 1.0f;
            }
            float fr = _2983;
            float _2986;
            if (transmits)
            {
                _2986 = reflects ? fr : 0.0f;
            }
            else
            {
                _2986 = 1.0f;
            }
            float pReflect = _2986;
            if (u.z < pReflect)
            {
                float3 i = reflect(-o, m);
                if (i.z <= 0.0f)
                {
                    return s;
                }
                float3 _2988;
                if (above)
                {
                    _2988 = i;
                }
                else
                {
                    _2988 = -i;
                }
                s.wi = _2988;
                s.delta = delta;
                if (delta)
                {
                    float3 _2990;
                    if (l.kind == 1)
                    {
                        float3 _2991;
                        if (above)
                        {
                            _2991 = l.c0;
                        }
                        else
                        {
                            _2991 = 1.0f.xxx;
                        }
                        _2990 = _2991;
                    }
                    else
                    {
                        _2990 = 1.0f.xxx;
                    }
                    float3 tint = _2990;
                    s.value = f * tint;
                    s.pdf = pReflect;
                }
                else
                {
                    MxcLobe param_9 = l;
                    float3 param_10 = wo;
                    float3 param_11 = s.wi;
                    s.value = mxc_lobe_eval(param_9, param_10, param_11);
                    MxcLobe param_12 = l;
                    float3 param_13 = wo;
                    float3 param_14 = s.wi;
                    s.pdf = mxc_lobe_pdf(param_12, param_13, param_14);
                }
                s.valid = s.pdf > 0.0f;
                return s;
            }
            return s;
        }
        default:
        {
            if (wo.z <= 0.0f)
            {
                return s;
            }
            float2 param_15 = u.xy;
            s.wi = mxc_sample_cosine(param_15);
            MxcLobe param_16 = l;
            float3 param_17 = wo;
            float3 param_18 = s.wi;
            s.value = mxc_lobe_eval(param_16, param_17, param_18);
            MxcLobe param_19 = l;
            float3 param_20 = wo;
            float3 param_21 = s.wi;
            s.pdf = mxc_lobe_pdf(param_19, param_20, param_21);
            s.valid = s.pdf > 0.0f;
            return s;
        }
    }
}

float3 mxc_to_world(float3x3 frame, float3 v)
{
    return ((frame[0] * v.x) + (frame[1] * v.y)) + (frame[2] * v.z);
}

float3 mxc_lobe_absorption(MxcLobe l, float mu)
{
    return 1.0f.xxx;
}

MxcSample mxc_closure_sample_direction(MxcClosure c, float3 wo, float3 u)
{
    MxcSample s;
    s.valid = false;
    s.delta = false;
    s.evaluate = false;
    s.pdf = 0.0f;
    s.weight = 0.0f.xxx;
    s.wi = wo;
    float total = c.choiceTotal;
    if ((c.count == 0) || (total <= 0.0f))
    {
        return s;
    }
    float x = u.z * total;
    int chosen = -1;
    float before = 0.0f;
    float p = 0.0f;
    float lastBefore = 0.0f;
    int last = -1;
    for (int k = 0; k < c.count; k++)
    {
        float pk = c.choice[k];
        if (pk <= 0.0f)
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
    if (p <= 0.0f)
    {
        return s;
    }
    float uz = clamp((x - before) / p, 0.0f, 0.999999940395355224609375f);
    MxcLobe l = c.lobes[chosen];
    float3 param = l.N;
    float3 param_1 = l.T;
    float3x3 frame = mxc_frame(param, param_1);
    float3x3 param_2 = frame;
    float3 param_3 = wo;
    float3 o = mxc_to_local(param_2, param_3);
    float q = c.msPick[chosen];
    bool shaped = uz < q;
    bool reflected = true;
    if (shaped)
    {
        float v = uz / q;
        float split = c.msSplit[chosen];
        reflected = v < split;
        float _3740;
        if (reflected)
        {
            _3740 = v / max(split, 9.9999999747524270787835121154785e-07f);
        }
        else
        {
            _3740 = (v - split) / max(1.0f - split, 9.9999999747524270787835121154785e-07f);
        }
        uz = _3740;
    }
    else
    {
        uz = (uz - q) / (1.0f - q);
    }
    MxcLobe _3742;
    if (shaped)
    {
        MxcLobe param_4 = l;
        bool param_5 = !reflected;
        _3742 = mxc_ms_lobe(param_4, param_5);
    }
    else
    {
        _3742 = l;
    }
    MxcLobe m = _3742;
    MxcLobe param_6 = m;
    float3 param_7 = o;
    float3 param_8 = float3(u.xy, min(uz, 0.999999940395355224609375f));
    MxcLobeSample ls = mxc_lobe_sample(param_6, param_7, param_8);
    if (!ls.valid)
    {
        return s;
    }
    float3x3 param_9 = frame;
    float3 param_10 = ls.wi;
    s.wi = mxc_to_world(param_9, param_10);
    if (ls.delta)
    {
        s.delta = true;
        s.pdf = (ls.pdf * p) / total;
        MxcLobe param_11 = l;
        float param_12 = abs(ls.wi.z);
        s.weight = (((l.weight * c.ms[chosen]) * mxc_lobe_absorption(param_11, param_12)) * ls.value) / s.pdf.xxx;
        s.valid = s.pdf > 0.0f;
        return s;
    }
    s.evaluate = true;
    s.valid = true;
    return s;
}

float3 mxc_exit_direction(float3 d, float3 t)
{
    float3 axis = cross(d, t);
    float s = length(axis);
    if (s < 9.9999999747524270787835121154785e-07f)
    {
        return t;
    }
    axis /= s.xxx;
    float c = dot(d, t);
    return ((t * c) + (cross(axis, t) * s)) + ((axis * dot(axis, t)) * (1.0f - c));
}

float3 mxc_sky(float3 d)
{
    float y = clamp(d.y, -1.0f, 1.0f);
    float3 horizon = float3(1.0f, 0.959999978542327880859375f, 0.89999997615814208984375f);
    float3 zenith = float3(0.300000011920928955078125f, 0.5f, 0.949999988079071044921875f);
    float3 ground = float3(0.1599999964237213134765625f, 0.14499999582767486572265625f, 0.12999999523162841796875f);
    if (y >= 0.0f)
    {
        return lerp(horizon, zenith, sqrt(y).xxx);
    }
    return lerp(horizon, ground, sqrt(-y).xxx);
}

float3 mxc_env_to_map(float3 w, float angle)
{
    float c = cos(angle);
    float s = sin(angle);
    return float3((c * w.x) - (s * w.z), w.y, (s * w.x) + (c * w.z));
}

float2 mxc_env_uv(float3 d)
{
    float _4232;
    if ((abs(d.x) + abs(d.z)) > 9.9999999600419720025001879548654e-13f)
    {
        _4232 = 0.5f + (atan2(d.x, -d.z) * 0.15915493667125701904296875f);
    }
    else
    {
        _4232 = 0.5f;
    }
    float u = _4232;
    float v = atan2(length(d.xz), d.y) * 0.3183098733425140380859375f;
    return float2(u, v);
}

float3 mxc_env_lookup(float3 d)
{
    float3 param = d;
    return mxc_env_radiance.SampleLevel(_mxc_env_radiance_sampler, mxc_env_uv(param), 0.0f).xyz;
}

float3 mxc_environment(float3 d)
{
    int code = mxc_environment_code();
    if (code == 1)
    {
        return mxc_view_environment.x.xxx;
    }
    if (code == 2)
    {
        float3 param = d;
        return mxc_sky(param) * mxc_view_environment.x;
    }
    if (code == 3)
    {
        float3 param_1 = d;
        float param_2 = mxc_view_environment.z;
        float3 param_3 = mxc_env_to_map(param_1, param_2);
        return mxc_env_lookup(param_3) * mxc_view_environment.x;
    }
    return 0.0f.xxx;
}

uint mxc_env_cell(float3 d)
{
    float3 param = d;
    float2 uv = mxc_env_uv(param);
    uint2 size = max(_235.Load4(0).xy, uint2(1u, 1u));
    uint i = min(uint(max(uv.x, 0.0f) * float(size.x)), (size.x - 1u));
    uint j = min(uint(max(uv.y, 0.0f) * float(size.y)), (size.y - 1u));
    return (j * size.x) + i;
}

float mxc_env_pdf(float3 d)
{
    float3 param = d;
    return asfloat(_235.Load(mxc_env_cell(param) * 16 + 24));
}

float mxc_power_heuristic(float a, float b)
{
    float a2 = a * a;
    float b2 = b * b;
    float _4622;
    if ((a2 + b2) > 0.0f)
    {
        _4622 = a2 / (a2 + b2);
    }
    else
    {
        _4622 = 0.0f;
    }
    return _4622;
}

float3 mxc_env_sample(float4 u, out float pdf)
{
    uint2 size = max(_235.Load4(0).xy, uint2(1u, 1u));
    uint n = size.x * size.y;
    uint k = min(uint(u.x * float(n)), (n - 1u));
    float4 cell = asfloat(_235.Load4(k * 16 + 16));
    if (u.y >= cell.x)
    {
        k = min(asuint(cell.y), (n - 1u));
    }
    pdf = asfloat(_235.Load(k * 16 + 24));
    uint i = k % size.x;
    uint j = k / size.x;
    float phi = 6.283185482025146484375f * (((float(i) + u.z) / float(size.x)) - 0.5f);
    float y0 = cos((3.1415927410125732421875f * float(j)) / float(size.y));
    float y1 = cos((3.1415927410125732421875f * float(j + 1u)) / float(size.y));
    float y = lerp(y0, y1, u.w);
    float param = 1.0f - (y * y);
    float r = mxc_safe_sqrt(param);
    return float3(r * sin(phi), y, (-r) * cos(phi));
}

float3 mxc_env_to_world(float3 m, float angle)
{
    float c = cos(angle);
    float s = sin(angle);
    return float3((c * m.x) + (s * m.z), m.y, ((-s) * m.x) + (c * m.z));
}

float3 mxc_closure_eval_pdf(MxcClosure c, float3 wo, float3 wi, bool wantPdf, inout float pdf)
{
    float3 f = 0.0f.xxx;
    float p = 0.0f;
    MxcLobe _3520;
    float3 _3524;
    float3 _3525;
    float3 _3526;
    float _3531;
    float _3532;
    for (int k = 0; k < c.count; k++)
    {
        MxcLobe l = c.lobes[k];
        if (all(bool3(l.weight.x == 0.0f.xxx.x, l.weight.y == 0.0f.xxx.y, l.weight.z == 0.0f.xxx.z)))
        {
            continue;
        }
        float3 param = l.N;
        float3 param_1 = l.T;
        float3x3 frame = mxc_frame(param, param_1);
        float3x3 param_2 = frame;
        float3 param_3 = wo;
        float3 o = mxc_to_local(param_2, param_3);
        float3x3 param_4 = frame;
        float3 param_5 = wi;
        float3 i = mxc_to_local(param_4, param_5);
        float3 fk = 0.0f.xxx;
        float pk = 0.0f;
        int passes = (c.msPick[k] > 0.0f) ? 2 : 1;
        for (int _pass = 0; _pass < passes; _pass++)
        {
            bool shaped = _pass == 1;
            if (shaped)
            {
                MxcLobe param_6 = l;
                bool param_7 = i.z < 0.0f;
                _3520 = mxc_ms_lobe(param_6, param_7);
            }
            else
            {
                _3520 = l;
            }
            MxcLobe m = _3520;
            if (shaped)
            {
                if (i.z > 0.0f)
                {
                    _3525 = c.msLobe[k];
                }
                else
                {
                    _3525 = c.msLobeT[k];
                }
                _3524 = _3525;
            }
            else
            {
                if ((o.z * i.z) < 0.0f)
                {
                    _3526 = c.msT[k].xxx;
                }
                else
                {
                    _3526 = c.ms[k];
                }
                _3524 = _3526;
            }
            float3 scale = _3524;
            MxcLobe param_8 = m;
            float3 param_9 = o;
            float3 param_10 = i;
            fk += (scale * mxc_lobe_eval(param_8, param_9, param_10));
            if (wantPdf)
            {
                if (shaped)
                {
                    if (i.z > 0.0f)
                    {
                        _3532 = c.msSplit[k];
                    }
                    else
                    {
                        _3532 = 1.0f - c.msSplit[k];
                    }
                    _3531 = c.msPick[k] * _3532;
                }
                else
                {
                    _3531 = 1.0f - c.msPick[k];
                }
                float share = _3531;
                MxcLobe param_11 = m;
                float3 param_12 = o;
                float3 param_13 = i;
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
    float _3538;
    if (c.choiceTotal > 0.0f)
    {
        _3538 = p / c.choiceTotal;
    }
    else
    {
        _3538 = 0.0f;
    }
    pdf = _3538;
    return f;
}

void frag_main()
{
    mxc_texture_footprint = 1.0f;
    MxcGeometry g;
    g.P = vPosition;
    g.Pobj = vObjectPosition;
    float3 param = vNormal;
    float3 param_1 = float3(0.0f, 0.0f, 1.0f);
    float3 N = mxc_safe_normalize(param, param_1);
    if (!gl_FrontFacing)
    {
        N = -N;
    }
    float3 param_2 = mxc_view_eye.xyz - vPosition;
    float3 param_3 = N;
    float3 wo = mxc_safe_normalize(param_2, param_3);
    float facing = dot(wo, N);
    if (facing < 0.00999999977648258209228515625f)
    {
        N = normalize(N + (wo * (0.00999999977648258209228515625f - facing)));
    }
    float handedness = (vTangent.w < 0.0f) ? (-1.0f) : 1.0f;
    float3 param_4 = N;
    float3 param_5 = vTangent.xyz;
    float3x3 frame = mxc_frame(param_4, param_5);
    g.N = N;
    g.T = frame[0];
    g.B = frame[1] * handedness;
    float3 param_6 = vObjectNormal;
    float3 param_7 = float3(0.0f, 0.0f, 1.0f);
    g.Nobj = mxc_safe_normalize(param_6, param_7);
    float3 param_8 = g.Nobj;
    float3 param_9 = vObjectTangent;
    float3x3 objectFrame = mxc_frame(param_8, param_9);
    g.Tobj = objectFrame[0];
    g.Bobj = objectFrame[1] * handedness;
    g.uv = vUv;
    g.color = 1.0f.xxxx;
    g.objectToWorld = mxc_view_objectToWorld;
    g.frame = asfloat(mxc_params.Load(4));
    g.time = asfloat(mxc_params.Load(8));
    mxc_texture_footprint = mxc_view_jitter.z;
    if (!(mxc_texture_footprint > 0.0f))
    {
        mxc_texture_footprint = 1.0f;
    }
    uint param_10 = uint(mxc_view_counts.z) + 7u;
    uint param_11 = uint(gl_FragCoord.y) + mxc_pcg(param_10);
    uint param_12 = uint(gl_FragCoord.x) ^ mxc_pcg(param_11);
    uint param_13 = mxc_pcg(param_12);
    mxc_closure_seed(param_13);
    MxcGeometry param_14 = g;
    float3 param_15 = wo;
    MxcClosure param_16;
    mxc_material_closure(param_14, param_15, param_16);
    MxcClosure c = param_16;
    float3 radiance = c.emission * mxc_view_environment.y;
    int lights = mxc_light_count();
    int kinds = mxc_light_kinds();
    bool image = mxc_environment_code() == 3;
    int _291;
    if (mxc_environment_code() != 0)
    {
        _291 = max(mxc_view_counts.w, 1);
    }
    else
    {
        _291 = 0;
    }
    int n = _291;
    uint param_17 = uint(mxc_view_counts.z);
    uint param_18 = uint(gl_FragCoord.y) + mxc_pcg(param_17);
    uint param_19 = uint(gl_FragCoord.x) + mxc_pcg(param_18);
    uint seed = mxc_pcg(param_19);
    uint param_20 = uint(gl_FragCoord.y) + 2654435769u;
    uint param_21 = uint(gl_FragCoord.x) ^ mxc_pcg(param_20);
    uint pixel = mxc_pcg(param_21);
    uint param_22 = pixel;
    float _539 = mxc_uniform(param_22);
    pixel = param_22;
    uint param_23 = pixel;
    float _543 = mxc_uniform(param_23);
    pixel = param_23;
    uint param_24 = pixel;
    float _546 = mxc_uniform(param_24);
    pixel = param_24;
    uint param_25 = pixel;
    float _549 = mxc_uniform(param_25);
    pixel = param_25;
    float4 shift = float4(_539, _543, _546, _549);
    float3 sum = 0.0f.xxx;
    int _308;
    MxcSample smp;
    float3 _325;
    float3 _326;
    float _331;
    float param_49;
    int _355;
    float param_59;
    float _371;
    for (int b = 0; b < max(n, int(lights > 0)); b++)
    {
        int batchLights = (b == 0) ? lights : 0;
        if (b < n)
        {
            _308 = 1 + int(image);
        }
        else
        {
            _308 = 0;
        }
        int batchSamples = _308;
        uint index = (uint(mxc_view_counts.z) * uint(max(n, 1))) + uint(b);
        uint param_26 = index;
        uint param_27 = 2u;
        float _589 = mxc_radical_inverse(param_26, param_27);
        uint param_28 = index;
        uint param_29 = 3u;
        float _592 = mxc_radical_inverse(param_28, param_29);
        uint param_30 = index;
        uint param_31 = 5u;
        float _594 = mxc_radical_inverse(param_30, param_31);
        uint param_32 = index;
        uint param_33 = 7u;
        float _596 = mxc_radical_inverse(param_32, param_33);
        float4 choice = frac(float4(_589, _592, _594, _596) + shift);
        smp.valid = false;
        smp.evaluate = false;
        smp.delta = false;
        smp.pdf = 0.0f;
        smp.weight = 0.0f.xxx;
        smp.wi = N;
        if (n > 0)
        {
            MxcClosure param_34 = c;
            float3 param_35 = wo;
            float3 param_36 = float3(choice.z, choice.w, choice.x);
            smp = mxc_closure_sample_direction(param_34, param_35, param_36);
        }
        bool above = dot(smp.wi, N) > 0.0f;
        if (smp.valid)
        {
            if (above)
            {
                _326 = smp.wi;
            }
            else
            {
                float3 param_37 = -wo;
                float3 param_38 = smp.wi;
                _326 = mxc_exit_direction(param_37, param_38);
            }
            float3 param_39 = _326;
            _325 = mxc_environment(param_39);
        }
        else
        {
            _325 = 0.0f.xxx;
        }
        float3 seen = _325;
        bool _654 = (b < n) && smp.valid;
        bool _660;
        if (_654)
        {
            _660 = !smp.evaluate;
        }
        else
        {
            _660 = _654;
        }
        if (_660)
        {
            bool _665 = image && above;
            bool _671;
            if (_665)
            {
                _671 = !smp.delta;
            }
            else
            {
                _671 = _665;
            }
            if (_671)
            {
                float3 param_40 = smp.wi;
                float param_41 = mxc_view_environment.z;
                float3 param_42 = mxc_env_to_map(param_40, param_41);
                float param_43 = smp.pdf;
                float param_44 = mxc_env_pdf(param_42);
                _331 = mxc_power_heuristic(param_43, param_44);
            }
            else
            {
                _331 = 1.0f;
            }
            float w = _331;
            sum += ((smp.weight * w) * seen);
        }
        float3 m = 0.0f.xxx;
        float lightPdf = 0.0f;
        float3 imageWi = N;
        float3 imageSeen = 0.0f.xxx;
        if (image && (b < n))
        {
            uint param_45 = seed;
            float _707 = mxc_uniform(param_45);
            seed = param_45;
            uint param_46 = seed;
            float _710 = mxc_uniform(param_46);
            seed = param_46;
            uint param_47 = seed;
            float _713 = mxc_uniform(param_47);
            seed = param_47;
            float4 v = float4(choice.y, _707, _710, _713);
            float4 param_48 = v;
            float3 _717 = mxc_env_sample(param_48, param_49);
            lightPdf = param_49;
            m = _717;
            float3 param_50 = m;
            float param_51 = mxc_view_environment.z;
            imageWi = mxc_env_to_world(param_50, param_51);
            bool _726 = lightPdf > 0.0f;
            bool _733;
            if (_726)
            {
                _733 = dot(imageWi, N) > 0.0f;
            }
            else
            {
                _733 = _726;
            }
            if (_733)
            {
                float3 param_52 = imageWi;
                imageSeen = mxc_environment(param_52);
            }
        }
        for (int j = 0; j < (batchLights + batchSamples); j++)
        {
            float3 wi = N;
            float3 incoming = 0.0f.xxx;
            bool use = true;
            if ((n == 0) || (j < batchLights))
            {
                _355 = 0;
            }
            else
            {
                _355 = (j == ((batchLights + 1) - 1)) ? 1 : 2;
            }
            int strategy = _355;
            if (strategy == 0)
            {
                float4 light = mxc_view_lightVector[j];
                incoming = mxc_view_lightRadiance[j].xyz;
                bool _778 = kinds == 1;
                bool _791;
                if (!_778)
                {
                    bool _784 = (kinds & 1) != 0;
                    bool _790;
                    if (_784)
                    {
                        _790 = light.w == 0.0f;
                    }
                    else
                    {
                        _790 = _784;
                    }
                    _791 = _790;
                }
                else
                {
                    _791 = _778;
                }
                bool directional = _791;
                if (directional)
                {
                    float3 param_53 = light.xyz;
                    float3 param_54 = N;
                    wi = mxc_safe_normalize(param_53, param_54);
                }
                else
                {
                    float3 d = light.xyz - vPosition;
                    float d2 = max(dot(d, d), 9.9999999392252902907785028219223e-09f);
                    wi = d * rsqrt(d2);
                    incoming /= d2.xxx;
                    bool _818 = (kinds & 4) != 0;
                    bool _824;
                    if (_818)
                    {
                        _824 = light.w == 2.0f;
                    }
                    else
                    {
                        _824 = _818;
                    }
                    if (_824)
                    {
                        float4 spot = mxc_view_lightSpot[j];
                        incoming *= smoothstep(spot.w, mxc_view_lightRadiance[j].w, dot(-wi, spot.xyz));
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
                    bool _859 = lightPdf > 0.0f;
                    bool _866;
                    if (_859)
                    {
                        _866 = dot(imageWi, N) > 0.0f;
                    }
                    else
                    {
                        _866 = _859;
                    }
                    use = _866;
                }
            }
            MxcClosure param_55 = c;
            float3 param_56 = wo;
            float3 param_57 = wi;
            bool param_58 = strategy != 0;
            float3 _872 = mxc_closure_eval_pdf(param_55, param_56, param_57, param_58, param_59);
            float pdf = param_59;
            float3 f = _872;
            if (strategy == 0)
            {
                radiance += (f * incoming);
            }
            else
            {
                if (strategy == 1)
                {
                    if (use && (pdf > 0.0f))
                    {
                        if (image && above)
                        {
                            float3 param_60 = wi;
                            float param_61 = mxc_view_environment.z;
                            float3 param_62 = mxc_env_to_map(param_60, param_61);
                            float param_63 = pdf;
                            float param_64 = mxc_env_pdf(param_62);
                            _371 = mxc_power_heuristic(param_63, param_64);
                        }
                        else
                        {
                            _371 = 1.0f;
                        }
                        float w_1 = _371;
                        sum += (((f * w_1) / pdf.xxx) * incoming);
                    }
                }
                else
                {
                    if (use)
                    {
                        float3 param_65 = m;
                        float param_66 = mxc_env_pdf(param_65);
                        float param_67 = pdf;
                        float w_2 = mxc_power_heuristic(param_66, param_67);
                        sum += (((f * w_2) * incoming) / lightPdf.xxx);
                    }
                }
            }
        }
    }
    radiance += (sum / float(max(n, 1)).xxx);
    float3 param_68 = c.transparency;
    float coverage = 1.0f - clamp(mxc_luminance(param_68), 0.0f, 1.0f);
    outColor = float4(radiance, coverage);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    gl_FragCoord = stage_input.gl_FragCoord;
    gl_FragCoord.w = 1.0 / gl_FragCoord.w;
    gl_FrontFacing = stage_input.gl_FrontFacing;
    vPosition = stage_input.vPosition;
    vObjectPosition = stage_input.vObjectPosition;
    vNormal = stage_input.vNormal;
    vTangent = stage_input.vTangent;
    vObjectNormal = stage_input.vObjectNormal;
    vObjectTangent = stage_input.vObjectTangent;
    vUv = stage_input.vUv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.outColor = outColor;
    return stage_output;
}
// ==== vertex (main) ====
#ifndef SPIRV_CROSS_CONSTANT_ID_0
#define SPIRV_CROSS_CONSTANT_ID_0 -1
#endif
static const int MXC_ENVIRONMENT = SPIRV_CROSS_CONSTANT_ID_0;
#ifndef SPIRV_CROSS_CONSTANT_ID_1
#define SPIRV_CROSS_CONSTANT_ID_1 -1
#endif
static const int MXC_LIGHT_COUNT = SPIRV_CROSS_CONSTANT_ID_1;
#ifndef SPIRV_CROSS_CONSTANT_ID_2
#define SPIRV_CROSS_CONSTANT_ID_2 -1
#endif
static const int MXC_LIGHT_KINDS = SPIRV_CROSS_CONSTANT_ID_2;

cbuffer MxcView : register(b1, space0)
{
    row_major float4x4 mxc_view_objectToWorld : packoffset(c0);
    row_major float4x4 mxc_view_normalToWorld : packoffset(c4);
    row_major float4x4 mxc_view_worldToClip : packoffset(c8);
    float4 mxc_view_eye : packoffset(c12);
    float4 mxc_view_jitter : packoffset(c13);
    float4 mxc_view_lightVector[8] : packoffset(c14);
    float4 mxc_view_lightSpot[8] : packoffset(c22);
    float4 mxc_view_lightRadiance[8] : packoffset(c30);
    int4 mxc_view_counts : packoffset(c38);
    float4 mxc_view_environment : packoffset(c39);
};


static float4 gl_Position;
static float3 inPosition;
static float3 vPosition;
static float3 vNormal;
static float3 inNormal;
static float4 vTangent;
static float4 inTangent;
static float2 vUv;
static float2 inUv;
static float3 vObjectPosition;
static float3 vObjectNormal;
static float3 vObjectTangent;

struct SPIRV_Cross_Input
{
    float3 inPosition : TEXCOORD0;
    float3 inNormal : TEXCOORD1;
    float4 inTangent : TEXCOORD2;
    float2 inUv : TEXCOORD3;
};

struct SPIRV_Cross_Output
{
    float3 vPosition : TEXCOORD0;
    float3 vNormal : TEXCOORD1;
    float4 vTangent : TEXCOORD2;
    float2 vUv : TEXCOORD3;
    float3 vObjectPosition : TEXCOORD4;
    float3 vObjectNormal : TEXCOORD5;
    float3 vObjectTangent : TEXCOORD6;
    float4 gl_Position : SV_Position;
};

void vert_main()
{
    float4 world = mul(float4(inPosition, 1.0f), mxc_view_objectToWorld);
    vPosition = world.xyz;
    vNormal = mul(inNormal, float3x3(mxc_view_normalToWorld[0].xyz, mxc_view_normalToWorld[1].xyz, mxc_view_normalToWorld[2].xyz));
    vTangent = float4(mul(inTangent.xyz, float3x3(mxc_view_objectToWorld[0].xyz, mxc_view_objectToWorld[1].xyz, mxc_view_objectToWorld[2].xyz)), inTangent.w);
    vUv = inUv;
    vObjectPosition = inPosition;
    vObjectNormal = inNormal;
    vObjectTangent = inTangent.xyz;
    float4 clip = mul(world, mxc_view_worldToClip);
    precise float2 _105 = mxc_view_jitter.xy * clip.w;
    precise float2 _108 = clip.xy + _105;
    clip.x = _108.x;
    clip.y = _108.y;
    gl_Position = clip;
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    inPosition = stage_input.inPosition;
    inNormal = stage_input.inNormal;
    inTangent = stage_input.inTangent;
    inUv = stage_input.inUv;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output.vPosition = vPosition;
    stage_output.vNormal = vNormal;
    stage_output.vTangent = vTangent;
    stage_output.vUv = vUv;
    stage_output.vObjectPosition = vObjectPosition;
    stage_output.vObjectNormal = vObjectNormal;
    stage_output.vObjectTangent = vObjectTangent;
    return stage_output;
}
