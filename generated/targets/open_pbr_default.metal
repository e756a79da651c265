// ==== corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx: material Default, placements ====
// mxc_tables {"sampler":0,"texture":0}
// MxcView {"buffer":0}
// MxcParameters {"buffer":1}
// mxc_env_radiance {"sampler":1,"texture":1}
// MxcEnvDistribution {"buffer":2}
// ==== fragment (main0) ====
#pragma clang diagnostic ignored "-Wmissing-prototypes"
#pragma clang diagnostic ignored "-Wmissing-braces"

#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

template<typename T, size_t Num>
struct spvUnsafeArray
{
    T elements[Num ? Num : 1];
    
    thread T& operator [] (size_t pos) thread
    {
        return elements[pos];
    }
    constexpr const thread T& operator [] (size_t pos) const thread
    {
        return elements[pos];
    }
    
    device T& operator [] (size_t pos) device
    {
        return elements[pos];
    }
    constexpr const device T& operator [] (size_t pos) const device
    {
        return elements[pos];
    }
    
    constexpr const constant T& operator [] (size_t pos) const constant
    {
        return elements[pos];
    }
    
    threadgroup T& operator [] (size_t pos) threadgroup
    {
        return elements[pos];
    }
    constexpr const threadgroup T& operator [] (size_t pos) const threadgroup
    {
        return elements[pos];
    }
};

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
    spvUnsafeArray<MxcLobe, 2> lobes;
    int count;
    spvUnsafeArray<float, 2> choice;
    float choiceTotal;
    spvUnsafeArray<float3, 2> ms;
    spvUnsafeArray<float, 2> msT;
    spvUnsafeArray<float3, 2> msLobe;
    spvUnsafeArray<float3, 2> msLobeT;
    spvUnsafeArray<float, 2> msPick;
    spvUnsafeArray<float, 2> msSplit;
    float3 emission;
    float3 transparency;
};

struct MxcSample
{
    float3 wi;
    float3 weight;
    float pdf;
    short delta;
    short evaluate;
    short valid;
};

struct MxcView
{
    float4x4 objectToWorld;
    float4x4 normalToWorld;
    float4x4 worldToClip;
    float4 eye;
    float4 jitter;
    float4 lightVector[8];
    float4 lightSpot[8];
    float4 lightRadiance[8];
    int4 counts;
    float4 environment;
};

struct MxcParameters
{
    uint missing_textures;
    float frame;
    float time;
};

struct MxcLobeSample
{
    float3 wi;
    float3 value;
    float pdf;
    short delta;
    short valid;
};

struct MxcEnvDistribution
{
    uint4 mxc_env_size;
    float4 mxc_env_cells[1];
};

constant int MXC_ENVIRONMENT_tmp [[function_constant(0)]];
constant int MXC_ENVIRONMENT = is_function_constant_defined(MXC_ENVIRONMENT_tmp) ? MXC_ENVIRONMENT_tmp : -1;
constant bool _225 = (MXC_ENVIRONMENT != (-1));
constant int MXC_LIGHT_COUNT_tmp [[function_constant(1)]];
constant int MXC_LIGHT_COUNT = is_function_constant_defined(MXC_LIGHT_COUNT_tmp) ? MXC_LIGHT_COUNT_tmp : -1;
constant bool _227 = (MXC_LIGHT_COUNT != (-1));
constant int MXC_LIGHT_KINDS_tmp [[function_constant(2)]];
constant int MXC_LIGHT_KINDS = is_function_constant_defined(MXC_LIGHT_KINDS_tmp) ? MXC_LIGHT_KINDS_tmp : -1;
constant bool _229 = (MXC_LIGHT_KINDS != (-1));
constant int _230 = _229 ? MXC_LIGHT_KINDS : 7;

struct main0_out
{
    float4 outColor [[color(0)]];
};

struct main0_in
{
    float3 vPosition [[user(locn0)]];
    float3 vNormal [[user(locn1)]];
    float4 vTangent [[user(locn2)]];
    float2 vUv [[user(locn3)]];
    float3 vObjectPosition [[user(locn4)]];
    float3 vObjectNormal [[user(locn5)]];
    float3 vObjectTangent [[user(locn6)]];
};

static inline __attribute__((always_inline))
float3 mxc_safe_normalize(thread const float3& v, thread const float3& fallback)
{
    float l2 = dot(v, v);
    float3 _959;
    if (l2 > 9.9999996826552253889678874634872e-21)
    {
        _959 = v * rsqrt(l2);
    }
    else
    {
        _959 = fallback;
    }
    return _959;
}

static inline __attribute__((always_inline))
float3x3 mxc_frame(thread const float3& N, thread const float3& T)
{
    float3 t = T - (N * dot(N, T));
    float l2 = dot(t, t);
    if (!(l2 > 9.9999999600419720025001879548654e-13))
    {
        float s = (N.z >= 0.0) ? 1.0 : (-1.0);
        float a = (-1.0) / (s + N.z);
        float b = (N.x * N.y) * a;
        t = float3(1.0 + (((s * N.x) * N.x) * a), s * b, (-s) * N.x);
    }
    else
    {
        t *= rsqrt(l2);
    }
    return float3x3(float3(t), float3(cross(N, t)), float3(N));
}

static inline __attribute__((always_inline))
uint mxc_pcg(thread const uint& v)
{
    uint state = (v * 747796405u) + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

static inline __attribute__((always_inline))
void mxc_closure_seed(thread const uint& seed)
{
}

static inline __attribute__((always_inline))
float3 mxc_to_local(thread const float3x3& frame, thread const float3& v)
{
    return float3(dot(v, frame[0]), dot(v, frame[1]), dot(v, frame[2]));
}

static inline __attribute__((always_inline))
bool mxc_is_delta(thread const float2& alpha)
{
    return fast::max(alpha.x, alpha.y) < 9.9999997473787516355514526367188e-05;
}

static inline __attribute__((always_inline))
bool mxc_index_matched(thread const MxcLobe& l)
{
    return abs(l.eta - 1.0) < 9.9999997473787516355514526367188e-05;
}

static inline __attribute__((always_inline))
bool mxc_dielectric_walk_split(thread const MxcLobe& l, thread const float3& wo)
{
    bool _2050 = wo.z <= 0.0;
    bool _2057;
    if (!_2050)
    {
        _2057 = l.eta < 1.0;
    }
    else
    {
        _2057 = _2050;
    }
    if (_2057)
    {
        return false;
    }
    return true;
}

static inline __attribute__((always_inline))
float4 mxc_table_at(thread const float& mu, thread const float& x, thread const float& firstRow, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    float2 t = (float2(sqrt(fast::clamp(mu, 0.0, 1.0)), fast::clamp(x, 0.0, 1.0)) * 31.0) + float2(0.5);
    return mxc_tables.sample(mxc_tablesSmplr, float2(t.x / 32.0, (firstRow + t.y) / 2070.0), level(0.0));
}

static inline __attribute__((always_inline))
float4 mxc_dielectric_table(thread const float& mu, thread const float& alpha, thread const float& e, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    float s = sqrt(fast::clamp(0.5 * (e - 1.0), 0.0, 1.0)) * 31.0;
    float s0 = fast::min(floor(s), 30.0);
    float x = sqrt(fast::max(alpha, 0.0));
    float param = mu;
    float param_1 = x;
    float param_2 = 32.0 * (1.0 + s0);
    float4 a = mxc_table_at(param, param_1, param_2, mxc_tables, mxc_tablesSmplr);
    float param_3 = mu;
    float param_4 = x;
    float param_5 = 32.0 * (2.0 + s0);
    float4 b = mxc_table_at(param_3, param_4, param_5, mxc_tables, mxc_tablesSmplr);
    return mix(a, b, float4(s - s0));
}

static inline __attribute__((always_inline))
float mxc_dielectric_albedo(thread const float& mu, thread const float& alpha, thread const float& eta, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    float _1590;
    if (eta >= 1.0)
    {
        _1590 = eta;
    }
    else
    {
        _1590 = 1.0 / fast::max(eta, 0.001000000047497451305389404296875);
    }
    float e = _1590;
    float param = mu;
    float param_1 = alpha;
    float param_2 = e;
    return mxc_dielectric_table(param, param_1, param_2, mxc_tables, mxc_tablesSmplr).x;
}

static inline __attribute__((always_inline))
float mxc_walk_eta_index(thread const float& eta)
{
    float e = fast::max(eta, 1.0);
    return fast::clamp((2.0 * (e - 1.0)) / (e + 1.0), 0.0, 1.0) * 12.0;
}

static inline __attribute__((always_inline))
float mxc_walk_texel(thread const float& column, thread const float& row, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    float2 t = float2(column + 0.5, row + 0.5) / float2(32.0, 2070.0);
    return mxc_tables.sample(mxc_tablesSmplr, t, level(0.0)).x;
}

static inline __attribute__((always_inline))
float mxc_walk_reflectance(thread const float& mu, thread const float& alpha, thread const float& eta, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    float param = eta;
    float fe = mxc_walk_eta_index(param);
    float e0 = fast::min(floor(fe), 11.0);
    float column = sqrt(fast::clamp(mu, 0.0, 1.0)) * 31.0;
    float row = 1654.0 + (sqrt(fast::clamp(alpha, 0.0, 1.0)) * 31.0);
    float param_1 = column;
    float param_2 = row + (e0 * 32.0);
    float a = mxc_walk_texel(param_1, param_2, mxc_tables, mxc_tablesSmplr);
    float param_3 = column;
    float param_4 = row + ((e0 + 1.0) * 32.0);
    float b = mxc_walk_texel(param_3, param_4, mxc_tables, mxc_tablesSmplr);
    return mix(a, b, fe - e0);
}

static inline __attribute__((always_inline))
float mxc_lobe_eta(thread const MxcLobe& l, thread const bool& above)
{
    float _1718;
    if (above)
    {
        _1718 = l.eta;
    }
    else
    {
        _1718 = 1.0 / l.eta;
    }
    return _1718;
}

static inline __attribute__((always_inline))
float mxc_dielectric_albedo_rt(thread const float& mu, thread const float& alpha, thread const float& eta, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    if (eta >= 1.0)
    {
        float param = mu;
        float param_1 = alpha;
        float param_2 = eta;
        return mxc_dielectric_table(param, param_1, param_2, mxc_tables, mxc_tablesSmplr).y;
    }
    float param_3 = mu;
    float param_4 = alpha;
    float param_5 = 1.0 / fast::max(eta, 0.001000000047497451305389404296875);
    return mxc_dielectric_table(param_3, param_4, param_5, mxc_tables, mxc_tablesSmplr).z;
}

static inline __attribute__((always_inline))
float4 mxc_table(thread const float& mu, thread const float& x, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    float param = mu;
    float param_1 = x;
    float param_2 = 0.0;
    return mxc_table_at(param, param_1, param_2, mxc_tables, mxc_tablesSmplr);
}

static inline __attribute__((always_inline))
float2 mxc_split_sum(thread const float& mu, thread const float& alpha, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    float param = mu;
    float param_1 = sqrt(fast::max(alpha, 0.0));
    return mxc_table(param, param_1, mxc_tables, mxc_tablesSmplr).xy;
}

static inline __attribute__((always_inline))
float mxc_lobe_cosine_below_coat(thread const MxcLobe& l, thread const float& mu)
{
    bool _1743 = l.kind == 1;
    bool _1749;
    if (_1743)
    {
        _1749 = l.etaAbove > 1.0;
    }
    else
    {
        _1749 = _1743;
    }
    if (_1749)
    {
        return sqrt(1.0 - ((1.0 - (mu * mu)) / (l.etaAbove * l.etaAbove)));
    }
    return mu;
}

static inline __attribute__((always_inline))
float mxc_fresnel_dielectric(thread const float& cosi, thread const float& eta)
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

static inline __attribute__((always_inline))
float3 mxc_lobe_fresnel(thread const MxcLobe& l, thread float& _cosh, thread const bool& above)
{
    float3 f = float3(1.0);
    if (above)
    {
        MxcLobe param = l;
        float param_1 = fast::clamp(_cosh, 0.0, 1.0);
        _cosh = mxc_lobe_cosine_below_coat(param, param_1);
    }
    if (l.kind == 1)
    {
        MxcLobe param_2 = l;
        bool param_3 = above;
        float param_4 = _cosh;
        float param_5 = mxc_lobe_eta(param_2, param_3);
        f = float3(mxc_fresnel_dielectric(param_4, param_5));
    }
    return f;
}

static inline __attribute__((always_inline))
float3 mxc_lobe_ms_scale(thread const MxcLobe& l, thread const float3& wo, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    bool _2181 = l.kind == 1;
    bool _2188;
    if (!_2181)
    {
        _2188 = l.kind == 2;
    }
    else
    {
        _2188 = _2181;
    }
    bool _2195;
    if (!_2188)
    {
        _2195 = l.kind == 3;
    }
    else
    {
        _2195 = _2188;
    }
    bool microfacet = _2195;
    bool _2197 = !microfacet;
    bool _2204;
    if (!_2197)
    {
        float2 param = l.alpha;
        _2204 = mxc_is_delta(param);
    }
    else
    {
        _2204 = _2197;
    }
    if (_2204)
    {
        return float3(1.0);
    }
    float alpha = sqrt(l.alpha.x * l.alpha.y);
    bool _2215 = l.kind == 1;
    bool _2220;
    if (_2215)
    {
        MxcLobe param_1 = l;
        _2220 = mxc_index_matched(param_1);
    }
    else
    {
        _2220 = _2215;
    }
    if (_2220)
    {
        return float3(1.0);
    }
    bool _2225 = l.kind == 1;
    bool _2232;
    if (_2225)
    {
        _2232 = (l.mode & 4) == 0;
    }
    else
    {
        _2232 = _2225;
    }
    if (_2232)
    {
        MxcLobe param_2 = l;
        float3 param_3 = wo;
        if (mxc_dielectric_walk_split(param_2, param_3))
        {
            float param_4 = wo.z;
            float param_5 = alpha;
            float param_6 = l.eta;
            float rss = mxc_dielectric_albedo(param_4, param_5, param_6, mxc_tables, mxc_tablesSmplr);
            float param_7 = wo.z;
            float param_8 = alpha;
            float param_9 = l.eta;
            return float3(fast::clamp(mxc_walk_reflectance(param_7, param_8, param_9, mxc_tables, mxc_tablesSmplr) / fast::max(rss, 9.9999997473787516355514526367188e-05), 1.0, 20.0));
        }
        MxcLobe param_10 = l;
        bool param_11 = wo.z >= 0.0;
        float param_12 = abs(wo.z);
        float param_13 = alpha;
        float param_14 = mxc_lobe_eta(param_10, param_11);
        float e = mxc_dielectric_albedo_rt(param_12, param_13, param_14, mxc_tables, mxc_tablesSmplr);
        float3 k = float3(1.0 / fast::max(e, 0.0500000007450580596923828125));
        return k;
    }
    float param_15 = fast::max(wo.z, 0.0);
    float param_16 = alpha;
    float2 ab = mxc_split_sum(param_15, param_16, mxc_tables, mxc_tablesSmplr);
    float e_1 = ab.x + ab.y;
    MxcLobe param_17 = l;
    float param_18 = 1.0;
    bool param_19 = true;
    float3 _2283 = mxc_lobe_fresnel(param_17, param_18, param_19);
    return float3(1.0) + ((_2283 * (1.0 - e_1)) / float3(fast::max(e_1, 0.0500000007450580596923828125)));
}

static inline __attribute__((always_inline))
float3 mxc_lobe_albedo_scaled(thread const MxcLobe& l, thread const float3& wo, thread const float3& ms, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    float mu = fast::clamp(wo.z, 0.0, 1.0);
    bool _2426 = l.kind == 1;
    bool _2433;
    if (!_2426)
    {
        _2433 = l.kind == 2;
    }
    else
    {
        _2433 = _2426;
    }
    bool _2440;
    if (!_2433)
    {
        _2440 = l.kind == 3;
    }
    else
    {
        _2440 = _2433;
    }
    if (_2440)
    {
        float alpha = sqrt(l.alpha.x * l.alpha.y);
        bool _2451 = l.kind == 1;
        bool _2458;
        if (_2451)
        {
            float2 param = l.alpha;
            _2458 = !mxc_is_delta(param);
        }
        else
        {
            _2458 = _2451;
        }
        if (_2458)
        {
            MxcLobe param_1 = l;
            float param_2 = mu;
            float param_3 = mxc_lobe_cosine_below_coat(param_1, param_2);
            float param_4 = alpha;
            float param_5 = l.eta;
            float3 e = float3(mxc_dielectric_albedo(param_3, param_4, param_5, mxc_tables, mxc_tablesSmplr));
            return fast::clamp((e * l.c0) * ms, float3(0.0), float3(1.0));
        }
        float param_6 = mu;
        float param_7 = alpha;
        float2 ab = mxc_split_sum(param_6, param_7, mxc_tables, mxc_tablesSmplr);
        MxcLobe param_8 = l;
        float param_9 = 1.0;
        bool param_10 = true;
        float3 _2482 = mxc_lobe_fresnel(param_8, param_9, param_10);
        float3 f0 = _2482;
        MxcLobe param_11 = l;
        float param_12 = 0.0;
        bool param_13 = true;
        float3 _2484 = mxc_lobe_fresnel(param_11, param_12, param_13);
        float3 f90 = _2484;
        float3 _2416;
        if (l.kind == 1)
        {
            _2416 = l.c0;
        }
        else
        {
            _2416 = float3(1.0);
        }
        float3 tint = _2416;
        float2 param_14 = l.alpha;
        if (mxc_is_delta(param_14))
        {
            MxcLobe param_15 = l;
            float param_16 = mu;
            bool param_17 = true;
            float3 _2501 = mxc_lobe_fresnel(param_15, param_16, param_17);
            return _2501 * tint;
        }
        return fast::clamp((((f0 * ab.x) + (f90 * ab.y)) * tint) * ms, float3(0.0), float3(1.0));
    }
    if (l.kind == 8)
    {
        return l.c0;
    }
    return l.c0;
}

static inline __attribute__((always_inline))
float3 mxc_lobe_albedo(thread const MxcLobe& l, thread const float3& wo, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    MxcLobe param = l;
    float3 param_1 = wo;
    MxcLobe param_2 = l;
    float3 param_3 = wo;
    float3 param_4 = mxc_lobe_ms_scale(param, param_1, mxc_tables, mxc_tablesSmplr);
    return mxc_lobe_albedo_scaled(param_2, param_3, param_4, mxc_tables, mxc_tablesSmplr);
}

static inline __attribute__((always_inline))
float3 mxc_lobe_layer_albedo(thread const MxcLobe& l, thread const float3& wo, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    bool _2555 = l.kind == 9;
    bool _2562;
    if (!_2555)
    {
        _2562 = l.kind == 10;
    }
    else
    {
        _2562 = _2555;
    }
    if (_2562)
    {
        MxcLobe white = l;
        white.c0 = float3(1.0);
        MxcLobe param = white;
        float3 param_1 = wo;
        return mxc_lobe_albedo(param, param_1, mxc_tables, mxc_tablesSmplr);
    }
    MxcLobe param_2 = l;
    float3 param_3 = wo;
    return mxc_lobe_albedo(param_2, param_3, mxc_tables, mxc_tablesSmplr);
}

static inline __attribute__((always_inline))
float mxc_lobe_ms_transmit(thread const MxcLobe& l, thread const float3& wo, thread const float3& ms, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    bool _2083 = l.kind != 1;
    bool _2090;
    if (!_2083)
    {
        float2 param = l.alpha;
        _2090 = mxc_is_delta(param);
    }
    else
    {
        _2090 = _2083;
    }
    bool _2096;
    if (!_2090)
    {
        MxcLobe param_1 = l;
        _2096 = mxc_index_matched(param_1);
    }
    else
    {
        _2096 = _2090;
    }
    bool _2104;
    if (!_2096)
    {
        _2104 = (l.mode & 4) != 0;
    }
    else
    {
        _2104 = _2096;
    }
    bool _2112;
    if (!_2104)
    {
        MxcLobe param_2 = l;
        float3 param_3 = wo;
        _2112 = !mxc_dielectric_walk_split(param_2, param_3);
    }
    else
    {
        _2112 = _2104;
    }
    if (_2112)
    {
        return ms.x;
    }
    float alpha = sqrt(l.alpha.x * l.alpha.y);
    float param_4 = wo.z;
    float param_5 = alpha;
    float param_6 = l.eta;
    float rss = mxc_dielectric_albedo(param_4, param_5, param_6, mxc_tables, mxc_tablesSmplr);
    float param_7 = wo.z;
    float param_8 = alpha;
    float param_9 = l.eta;
    float tss = mxc_dielectric_albedo_rt(param_7, param_8, param_9, mxc_tables, mxc_tablesSmplr) - rss;
    float param_10 = wo.z;
    float param_11 = alpha;
    float param_12 = l.eta;
    return fast::clamp((1.0 - mxc_walk_reflectance(param_10, param_11, param_12, mxc_tables, mxc_tablesSmplr)) / fast::max(tss, 0.0500000007450580596923828125), 1.0, 20.0);
}

static inline __attribute__((always_inline))
float mxc_luminance(thread const float3& c)
{
    return dot(c, float3(0.2125999927520751953125, 0.715200006961822509765625, 0.072200000286102294921875));
}

static inline __attribute__((always_inline))
float mxc_lobe_choice(thread const MxcLobe& l, thread const float3& woLocal, thread const float3& ms, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    if (all(l.weight == float3(0.0)))
    {
        return 0.0;
    }
    MxcLobe param = l;
    float3 param_1 = woLocal;
    float3 param_2 = ms;
    float3 param_3 = l.weight * mxc_lobe_albedo_scaled(param, param_1, param_2, mxc_tables, mxc_tablesSmplr);
    return fast::max(mxc_luminance(param_3), 0.0) + 9.9999997473787516355514526367188e-05;
}

static inline __attribute__((always_inline))
bool mxc_lobe_ms_shaped(thread const MxcLobe& l, thread const float3& wo)
{
    bool _2303 = wo.z <= 0.0;
    bool _2310;
    if (!_2303)
    {
        float2 param = l.alpha;
        _2310 = mxc_is_delta(param);
    }
    else
    {
        _2310 = _2303;
    }
    if (_2310)
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
    bool _2329 = l.kind == 1;
    bool _2336;
    if (_2329)
    {
        _2336 = (l.mode & 1) != 0;
    }
    else
    {
        _2336 = _2329;
    }
    bool _2343;
    if (_2336)
    {
        _2343 = (l.mode & 4) == 0;
    }
    else
    {
        _2343 = _2336;
    }
    bool _2349;
    if (_2343)
    {
        MxcLobe param_1 = l;
        _2349 = !mxc_index_matched(param_1);
    }
    else
    {
        _2349 = _2343;
    }
    bool _2355;
    if (_2349)
    {
        MxcLobe param_2 = l;
        float3 param_3 = wo;
        _2355 = mxc_dielectric_walk_split(param_2, param_3);
    }
    else
    {
        _2355 = _2349;
    }
    return _2355;
}

static inline __attribute__((always_inline))
bool mxc_lobe_transmits(thread const MxcLobe& l)
{
    return false;
}

static inline __attribute__((always_inline))
MxcLobe mxc_ms_lobe(thread const MxcLobe& l, thread const bool& transmitted)
{
    MxcLobe m = l;
    m.alpha = fast::min(l.alpha * (transmitted ? 3.0 : 1.5), float2(1.0));
    int _2361;
    if (transmitted)
    {
        _2361 = l.mode & (-2);
    }
    else
    {
        _2361 = l.mode & (-3);
    }
    m.mode = _2361;
    if (l.kind == 1)
    {
        m.c0 = float3(1.0);
        m.c1 = float3(1.0);
    }
    return m;
}

static inline __attribute__((always_inline))
void mxc_closure_prepare(thread MxcClosure& c, thread const float3& wo, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    c.choiceTotal = 0.0;
    float _3123;
    for (int k = 0; k < c.count; k++)
    {
        MxcLobe l = c.lobes[k];
        c.ms[k] = float3(1.0);
        c.msT[k] = 1.0;
        c.msLobe[k] = float3(0.0);
        c.msLobeT[k] = float3(0.0);
        c.msPick[k] = 0.0;
        c.msSplit[k] = 1.0;
        c.choice[k] = 0.0;
        if (all(l.weight == float3(0.0)))
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
        float3 ms = mxc_lobe_ms_scale(param_4, param_5, mxc_tables, mxc_tablesSmplr);
        MxcLobe param_6 = l;
        float3 param_7 = o;
        float3 param_8 = ms;
        c.msT[k] = mxc_lobe_ms_transmit(param_6, param_7, param_8, mxc_tables, mxc_tablesSmplr);
        MxcLobe param_9 = l;
        float3 param_10 = o;
        float3 param_11 = ms;
        c.choice[k] = mxc_lobe_choice(param_9, param_10, param_11, mxc_tables, mxc_tablesSmplr);
        c.choiceTotal += c.choice[k];
        MxcLobe param_12 = l;
        float3 param_13 = o;
        if (mxc_lobe_ms_shaped(param_12, param_13))
        {
            float alpha = sqrt(l.alpha.x * l.alpha.y);
            MxcLobe param_14 = l;
            float3 param_15 = o;
            float3 param_16 = float3(1.0);
            float3 reflected = mxc_lobe_albedo_scaled(param_14, param_15, param_16, mxc_tables, mxc_tablesSmplr);
            MxcLobe param_17 = l;
            float3 param_18 = o;
            float3 param_19 = ms;
            float3 addedR = fast::max(mxc_lobe_albedo_scaled(param_17, param_18, param_19, mxc_tables, mxc_tablesSmplr) - reflected, float3(0.0));
            float3 transmitted = float3(0.0);
            float3 addedT = float3(0.0);
            bool _3211 = l.kind == 1;
            bool _3216;
            if (_3211)
            {
                MxcLobe param_20 = l;
                _3216 = mxc_lobe_transmits(param_20);
            }
            else
            {
                _3216 = _3211;
            }
            if (_3216)
            {
                float param_21 = o.z;
                float param_22 = alpha;
                float param_23 = l.eta;
                float rss = mxc_dielectric_albedo(param_21, param_22, param_23, mxc_tables, mxc_tablesSmplr);
                float param_24 = o.z;
                float param_25 = alpha;
                float param_26 = l.eta;
                transmitted = l.c1 * fast::max(mxc_dielectric_albedo_rt(param_24, param_25, param_26, mxc_tables, mxc_tablesSmplr) - rss, 0.0);
                addedT = transmitted * fast::max(c.msT[k] - 1.0, 0.0);
            }
            MxcLobe param_27 = l;
            bool param_28 = false;
            MxcLobe mr = mxc_ms_lobe(param_27, param_28);
            MxcLobe param_29 = mr;
            float3 param_30 = o;
            float3 param_31 = float3(1.0);
            float3 broadR = mxc_lobe_albedo_scaled(param_29, param_30, param_31, mxc_tables, mxc_tablesSmplr);
            float broadT = 1.0;
            bool _3251 = l.kind == 1;
            bool _3256;
            if (_3251)
            {
                MxcLobe param_32 = l;
                _3256 = mxc_lobe_transmits(param_32);
            }
            else
            {
                _3256 = _3251;
            }
            if (_3256)
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
                broadT = mxc_dielectric_albedo_rt(param_35, param_36, param_37, mxc_tables, mxc_tablesSmplr) - mxc_dielectric_albedo(param_38, param_39, param_40, mxc_tables, mxc_tablesSmplr);
            }
            c.msLobe[k] = addedR / fast::max(broadR, float3(9.9999997473787516355514526367188e-05));
            c.msLobeT[k] = addedT / float3(fast::max(broadT, 9.9999997473787516355514526367188e-05));
            float3 param_41 = ((reflected + addedR) + transmitted) + addedT;
            float total = fast::max(mxc_luminance(param_41), 9.9999999747524270787835121154785e-07);
            float3 param_42 = addedR + addedT;
            float added = mxc_luminance(param_42);
            c.msPick[k] = 0.999000012874603271484375 * fast::min(added / total, 1.0);
            if (added > 0.0)
            {
                float3 param_43 = addedR;
                _3123 = mxc_luminance(param_43) / added;
            }
            else
            {
                _3123 = 1.0;
            }
            c.msSplit[k] = _3123;
            c.msT[k] = 1.0;
        }
        else
        {
            c.ms[k] = ms;
        }
    }
}

static inline __attribute__((always_inline))
void mxc_material_closure(thread const MxcGeometry& g, thread const float3& wo, thread MxcClosure& c, texture2d<float> mxc_tables, sampler mxc_tablesSmplr)
{
    float3 v5 = g.N;
    float3 v6 = g.T;
    c.emission = float3(0.0);
    c.transparency = float3(0.0);
    MxcLobe lobe0;
    lobe0.kind = 1;
    lobe0.mode = 1;
    lobe0.N = v5;
    lobe0.T = v6;
    lobe0.alpha = float2(0.0900000035762786865234375);
    lobe0.eta = 1.5;
    lobe0.etaAbove = 1.0;
    lobe0.c0 = float3(1.0);
    lobe0.c1 = float3(1.0);
    lobe0.c2 = float3(1.0);
    lobe0.p0 = 0.0;
    lobe0.p1 = 1.0;
    lobe0.film = float3(0.0);
    lobe0.tau = float3(0.0);
    lobe0.tauEta = 1.0;
    float3 param = lobe0.N;
    float3 param_1 = lobe0.T;
    float3x3 param_2 = mxc_frame(param, param_1);
    float3 param_3 = wo;
    MxcLobe param_4 = lobe0;
    float3 param_5 = mxc_to_local(param_2, param_3);
    float3 e1 = mxc_lobe_layer_albedo(param_4, param_5, mxc_tables, mxc_tablesSmplr);
    float3 w2 = float3(1.0) - e1;
    MxcLobe lobe3;
    lobe3.kind = 5;
    lobe3.mode = 1;
    lobe3.N = v5;
    lobe3.T = g.T;
    lobe3.alpha = float2(0.0);
    lobe3.eta = 1.5;
    lobe3.etaAbove = 1.0;
    lobe3.c0 = float3(0.800000011920928955078125);
    lobe3.c1 = float3(1.0);
    lobe3.c2 = float3(1.0);
    lobe3.p0 = 0.0;
    lobe3.p1 = 1.0;
    lobe3.film = float3(0.0);
    lobe3.tau = float3(0.0);
    lobe3.tauEta = 1.0;
    lobe0.weight = float3(1.0);
    c.lobes[0] = lobe0;
    lobe3.weight = w2;
    c.lobes[1] = lobe3;
    c.count = 2;
    MxcClosure param_6 = c;
    float3 param_7 = wo;
    mxc_closure_prepare(param_6, param_7, mxc_tables, mxc_tablesSmplr);
    c = param_6;
}

static inline __attribute__((always_inline))
int mxc_light_count(constant MxcView& mxc_view)
{
    int _4172;
    if (_227)
    {
        _4172 = MXC_LIGHT_COUNT;
    }
    else
    {
        _4172 = mxc_view.counts.x;
    }
    return min(_4172, 8);
}

static inline __attribute__((always_inline))
int mxc_light_kinds()
{
    return _230;
}

static inline __attribute__((always_inline))
int mxc_environment_code(constant MxcView& mxc_view)
{
    int _4164;
    if (_225)
    {
        _4164 = MXC_ENVIRONMENT;
    }
    else
    {
        _4164 = mxc_view.counts.y;
    }
    return _4164;
}

static inline __attribute__((always_inline))
float mxc_uniform(thread uint& seed)
{
    uint param = seed;
    seed = mxc_pcg(param);
    return float(seed >> uint(8)) * 5.9604644775390625e-08;
}

static inline __attribute__((always_inline))
float mxc_radical_inverse(thread uint& i, thread const uint& base)
{
    if (base == 2u)
    {
        return float(reverse_bits(i) >> uint(8)) * 5.9604644775390625e-08;
    }
    float inv = 1.0 / float(base);
    float f = inv;
    float r = 0.0;
    for (; i > 0u; i /= base)
    {
        r += (f * float(i % base));
        f *= inv;
    }
    return fast::min(r, 0.999999940395355224609375);
}

static inline __attribute__((always_inline))
float mxc_safe_sqrt(thread const float& x)
{
    return sqrt(fast::max(x, 0.0));
}

static inline __attribute__((always_inline))
float3 mxc_sample_cosine(thread const float2& u)
{
    float r = sqrt(u.x);
    float phi = 6.283185482025146484375 * u.y;
    float param = 1.0 - u.x;
    return float3(r * cos(phi), r * sin(phi), mxc_safe_sqrt(param));
}

static inline __attribute__((always_inline))
float2 mxc_rough_alpha(thread const float2& alpha)
{
    return fast::max(alpha, float2(9.9999997473787516355514526367188e-05));
}

static inline __attribute__((always_inline))
float mxc_ggx_d(thread const float3& m, thread float2& alpha)
{
    if (m.z <= 0.0)
    {
        return 0.0;
    }
    float2 param = alpha;
    alpha = mxc_rough_alpha(param);
    float3 s = float3(m.x / alpha.x, m.y / alpha.y, m.z);
    float d = dot(s, s);
    return 1.0 / ((((3.1415927410125732421875 * alpha.x) * alpha.y) * d) * d);
}

static inline __attribute__((always_inline))
float mxc_sqr(thread const float& x)
{
    return x * x;
}

static inline __attribute__((always_inline))
float mxc_ggx_lambda(thread const float3& v, thread float2& alpha)
{
    float2 param = alpha;
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

static inline __attribute__((always_inline))
float mxc_ggx_g2(thread const float3& wo, thread const float3& wi, thread const float2& alpha)
{
    float3 param = wo;
    float2 param_1 = alpha;
    float _1263 = mxc_ggx_lambda(param, param_1);
    float3 param_2 = wi;
    float2 param_3 = alpha;
    float _1267 = mxc_ggx_lambda(param_2, param_3);
    return 1.0 / ((1.0 + _1263) + _1267);
}

static inline __attribute__((always_inline))
float3 mxc_microfacet_reflect(thread const MxcLobe& l, thread const float3& wo, thread const float3& wi)
{
    bool _1814 = wo.z <= 0.0;
    bool _1821;
    if (!_1814)
    {
        _1821 = wi.z <= 0.0;
    }
    else
    {
        _1821 = _1814;
    }
    bool _1828;
    if (!_1821)
    {
        float2 param = l.alpha;
        _1828 = mxc_is_delta(param);
    }
    else
    {
        _1828 = _1821;
    }
    if (_1828)
    {
        return float3(0.0);
    }
    float3 h = fast::normalize(wo + wi);
    MxcLobe param_1 = l;
    float param_2 = fast::max(dot(wo, h), 0.0);
    bool param_3 = true;
    float3 _1840 = mxc_lobe_fresnel(param_1, param_2, param_3);
    float3 f = _1840;
    if (l.kind == 1)
    {
        f *= l.c0;
    }
    float3 param_4 = h;
    float2 param_5 = l.alpha;
    float _1854 = mxc_ggx_d(param_4, param_5);
    float3 param_6 = wo;
    float3 param_7 = wi;
    float2 param_8 = l.alpha;
    return ((f * _1854) * mxc_ggx_g2(param_6, param_7, param_8)) / float3(4.0 * wo.z);
}

static inline __attribute__((always_inline))
float mxc_fon(thread const float& sigma, thread const float3& wo, thread const float3& wi)
{
    float a = 1.0 / (1.0 + (0.2877933979034423828125 * sigma));
    float s = dot(wi, wo) - (wi.z * wo.z);
    float _1875;
    if (s > 0.0)
    {
        _1875 = fast::max(fast::max(wi.z, wo.z), 9.9999999747524270787835121154785e-07);
    }
    else
    {
        _1875 = 1.0;
    }
    float t = _1875;
    return (a + (((sigma * a) * s) / t)) * 0.3183098733425140380859375;
}

static inline __attribute__((always_inline))
float mxc_fon_albedo(thread const float& sigma, thread const float& mu)
{
    float a = 1.0 / (1.0 + (0.2877933979034423828125 * sigma));
    float c = fast::clamp(mu, 0.0, 1.0);
    float param = 1.0 - (c * c);
    float s = mxc_safe_sqrt(param);
    float theta = acos(c);
    float _1921;
    if (c > 9.9999997473787516355514526367188e-05)
    {
        _1921 = (1.0 - ((s * s) * s)) / c;
    }
    else
    {
        _1921 = 1.5 * c;
    }
    float tail = _1921;
    float g = ((s * (theta - (s * c))) + ((0.666666686534881591796875 * s) * tail)) - (0.666666686534881591796875 * s);
    return a + (((sigma * a) * g) * 0.3183098733425140380859375);
}

static inline __attribute__((always_inline))
float3 mxc_eon(thread const float3& rho, thread const float& sigma, thread const float3& wo, thread const float3& wi)
{
    float param = sigma;
    float3 param_1 = wo;
    float3 param_2 = wi;
    float3 f = rho * mxc_fon(param, param_1, param_2);
    float a = 1.0 / (1.0 + (0.2877933979034423828125 * sigma));
    float eavg = a * (1.0 + (0.072488211095333099365234375 * sigma));
    if (eavg < 0.999998986721038818359375)
    {
        float3 rhoMs = (((rho * rho) * eavg) / float3(1.0 - eavg)) / (float3(1.0) - (rho * (1.0 - eavg)));
        float param_3 = sigma;
        float param_4 = wi.z;
        float param_5 = sigma;
        float param_6 = wo.z;
        f += (((rhoMs * (1.0 - mxc_fon_albedo(param_3, param_4))) * (1.0 - mxc_fon_albedo(param_5, param_6))) * 0.3183098733425140380859375);
    }
    return f;
}

static inline __attribute__((always_inline))
float3 mxc_lobe_eval(thread const MxcLobe& l, thread const float3& wo, thread const float3& wi)
{
    switch (l.kind)
    {
        case 1:
        {
            if ((wo.z * wi.z) > 0.0)
            {
                if ((l.mode & 1) == 0)
                {
                    return float3(0.0);
                }
                if (wo.z < 0.0)
                {
                    MxcLobe m = l;
                    m.eta = 1.0 / l.eta;
                    m.c0 = float3(1.0);
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
            return float3(0.0);
        }
        case 2:
        case 3:
        {
            bool _2637 = l.kind == 3;
            bool _2644;
            if (_2637)
            {
                _2644 = (l.mode & 1) == 0;
            }
            else
            {
                _2644 = _2637;
            }
            if (_2644)
            {
                return float3(0.0);
            }
            MxcLobe param_6 = l;
            float3 param_7 = wo;
            float3 param_8 = wi;
            return mxc_microfacet_reflect(param_6, param_7, param_8);
        }
        case 5:
        {
            bool _2653 = wo.z > 0.0;
            bool _2659;
            if (_2653)
            {
                _2659 = wi.z > 0.0;
            }
            else
            {
                _2659 = _2653;
            }
            float3 _2588;
            if (_2659)
            {
                float3 param_9 = l.c0;
                float param_10 = l.p0;
                float3 param_11 = wo;
                float3 param_12 = wi;
                _2588 = mxc_eon(param_9, param_10, param_11, param_12) * wi.z;
            }
            else
            {
                _2588 = float3(0.0);
            }
            return _2588;
        }
        default:
        {
            return float3(0.0);
        }
    }
}

static inline __attribute__((always_inline))
float mxc_ggx_g1(thread const float3& v, thread const float2& alpha)
{
    float3 param = v;
    float2 param_1 = alpha;
    float _1249 = mxc_ggx_lambda(param, param_1);
    return 1.0 / (1.0 + _1249);
}

static inline __attribute__((always_inline))
float mxc_ggx_pdf_vndf(thread const float3& wo, thread const float3& m, thread const float2& alpha)
{
    if (wo.z <= 0.0)
    {
        return 0.0;
    }
    float3 param = wo;
    float2 param_1 = alpha;
    float3 param_2 = m;
    float2 param_3 = alpha;
    float _1422 = mxc_ggx_d(param_2, param_3);
    return ((mxc_ggx_g1(param, param_1) * fast::max(dot(wo, m), 0.0)) * _1422) / wo.z;
}

static inline __attribute__((always_inline))
float mxc_mean(thread const float3& c)
{
    return ((c.x + c.y) + c.z) * 0.3333333432674407958984375;
}

static inline __attribute__((always_inline))
float mxc_lobe_pdf(thread const MxcLobe& l, thread const float3& wo, thread const float3& wi)
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
                return 0.0;
            }
            bool above = wo.z > 0.0;
            float3 _2682;
            if (above)
            {
                _2682 = wo;
            }
            else
            {
                _2682 = -wo;
            }
            float3 o = _2682;
            float3 _2684;
            if (above)
            {
                _2684 = wi;
            }
            else
            {
                _2684 = -wi;
            }
            float3 i = _2684;
            if (i.z > 0.0)
            {
                float3 h = fast::normalize(o + i);
                float3 param_1 = o;
                float3 param_2 = h;
                float2 param_3 = l.alpha;
                float p = mxc_ggx_pdf_vndf(param_1, param_2, param_3) / (4.0 * fast::max(dot(o, h), 9.9999999747524270787835121154785e-07));
                if (l.kind == 2)
                {
                    return p;
                }
                if ((l.mode & 1) == 0)
                {
                    return 0.0;
                }
                MxcLobe param_4 = l;
                float param_5 = fast::max(dot(o, h), 0.0);
                bool param_6 = above;
                float3 _2780 = mxc_lobe_fresnel(param_4, param_5, param_6);
                float3 param_7 = _2780;
                float fr = mxc_mean(param_7);
                MxcLobe param_8 = l;
                bool _2784 = mxc_lobe_transmits(param_8);
                bool _2791;
                if (_2784)
                {
                    _2791 = (l.mode & 1) != 0;
                }
                else
                {
                    _2791 = _2784;
                }
                return p * (_2791 ? fr : 1.0);
            }
            return 0.0;
        }
        default:
        {
            bool _2704 = wo.z > 0.0;
            bool _2710;
            if (_2704)
            {
                _2710 = wi.z > 0.0;
            }
            else
            {
                _2710 = _2704;
            }
            float _2696;
            if (_2710)
            {
                _2696 = wi.z * 0.3183098733425140380859375;
            }
            else
            {
                _2696 = 0.0;
            }
            return _2696;
        }
    }
}

static inline __attribute__((always_inline))
float3 mxc_ggx_sample_vndf(thread const float3& wo, thread float2& alpha, thread const float2& u)
{
    float2 param = alpha;
    alpha = mxc_rough_alpha(param);
    float3 vh = fast::normalize(float3(alpha.x * wo.x, alpha.y * wo.y, wo.z));
    float lensq = (vh.x * vh.x) + (vh.y * vh.y);
    float3 _1279;
    if (lensq > 0.0)
    {
        _1279 = float3(-vh.y, vh.x, 0.0) * rsqrt(lensq);
    }
    else
    {
        _1279 = float3(1.0, 0.0, 0.0);
    }
    float3 t1 = _1279;
    float3 t2 = cross(vh, t1);
    float r = sqrt(u.x);
    float phi = 6.283185482025146484375 * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + vh.z);
    float param_1 = 1.0 - (p1 * p1);
    p2 = ((1.0 - s) * mxc_safe_sqrt(param_1)) + (s * p2);
    float param_2 = (1.0 - (p1 * p1)) - (p2 * p2);
    float3 nh = ((t1 * p1) + (t2 * p2)) + (vh * mxc_safe_sqrt(param_2));
    return fast::normalize(float3(alpha.x * nh.x, alpha.y * nh.y, fast::max(nh.z, 0.0)));
}

static inline __attribute__((always_inline))
MxcLobeSample mxc_lobe_sample(thread const MxcLobe& l, thread const float3& wo, thread const float3& u)
{
    MxcLobeSample s;
    s.valid = short(false);
    s.delta = short(false);
    s.pdf = 0.0;
    s.value = float3(0.0);
    s.wi = float3(0.0, 0.0, 1.0);
    switch (l.kind)
    {
        case 1:
        case 2:
        case 3:
        {
            bool above = wo.z > 0.0;
            float3 _2803;
            if (above)
            {
                _2803 = wo;
            }
            else
            {
                _2803 = -wo;
            }
            float3 o = _2803;
            if (o.z <= 0.0)
            {
                return s;
            }
            float2 param = l.alpha;
            bool delta = mxc_is_delta(param);
            float3 _2807;
            if (delta)
            {
                _2807 = float3(0.0, 0.0, 1.0);
            }
            else
            {
                float3 param_1 = o;
                float2 param_2 = l.alpha;
                float2 param_3 = u.xy;
                float3 _2908 = mxc_ggx_sample_vndf(param_1, param_2, param_3);
                _2807 = _2908;
            }
            float3 m = _2807;
            float hm = dot(o, m);
            bool _2915 = l.kind == 1;
            bool _2922;
            if (!_2915)
            {
                _2922 = l.kind == 3;
            }
            else
            {
                _2922 = _2915;
            }
            bool _2927;
            if (_2922)
            {
                MxcLobe param_4 = l;
                _2927 = mxc_lobe_transmits(param_4);
            }
            else
            {
                _2927 = _2922;
            }
            bool transmits = _2927;
            bool _2930 = l.kind == 2;
            bool _2938;
            if (!_2930)
            {
                _2938 = (l.mode & 1) != 0;
            }
            else
            {
                _2938 = _2930;
            }
            bool reflects = _2938;
            MxcLobe param_5 = l;
            float param_6 = fast::max(hm, 0.0);
            bool param_7 = above;
            float3 _2943 = mxc_lobe_fresnel(param_5, param_6, param_7);
            float3 f = _2943;
            float _2820;
            if (transmits)
            {
                float3 param_8 = f;
                _2820 = mxc_mean(param_8);
            }
            else
            {
                _2820 = 1.0;
            }
            float fr = _2820;
            float _2823;
            if (transmits)
            {
                _2823 = reflects ? fr : 0.0;
            }
            else
            {
                _2823 = 1.0;
            }
            float pReflect = _2823;
            if (u.z < pReflect)
            {
                float3 i = reflect(-o, m);
                if (i.z <= 0.0)
                {
                    return s;
                }
                float3 _2825;
                if (above)
                {
                    _2825 = i;
                }
                else
                {
                    _2825 = -i;
                }
                s.wi = _2825;
                s.delta = short(delta);
                if (delta)
                {
                    float3 _2827;
                    if (l.kind == 1)
                    {
                        float3 _2828;
                        if (above)
                        {
                            _2828 = l.c0;
                        }
                        else
                        {
                            _2828 = float3(1.0);
                        }
                        _2827 = _2828;
                    }
                    else
                    {
                        _2827 = float3(1.0);
                    }
                    float3 tint = _2827;
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
                s.valid = short(s.pdf > 0.0);
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
            s.valid = short(s.pdf > 0.0);
            return s;
        }
    }
}

static inline __attribute__((always_inline))
float3 mxc_to_world(thread const float3x3& frame, thread const float3& v)
{
    return ((frame[0] * v.x) + (frame[1] * v.y)) + (frame[2] * v.z);
}

static inline __attribute__((always_inline))
float3 mxc_lobe_absorption(thread const MxcLobe& l, thread const float& mu)
{
    return float3(1.0);
}

static inline __attribute__((always_inline))
MxcSample mxc_closure_sample_direction(thread const MxcClosure& c, thread const float3& wo, thread const float3& u)
{
    MxcSample s;
    s.valid = short(false);
    s.delta = short(false);
    s.evaluate = short(false);
    s.pdf = 0.0;
    s.weight = float3(0.0);
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
    float uz = fast::clamp((x - before) / p, 0.0, 0.999999940395355224609375);
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
        float _3577;
        if (reflected)
        {
            _3577 = v / fast::max(split, 9.9999999747524270787835121154785e-07);
        }
        else
        {
            _3577 = (v - split) / fast::max(1.0 - split, 9.9999999747524270787835121154785e-07);
        }
        uz = _3577;
    }
    else
    {
        uz = (uz - q) / (1.0 - q);
    }
    MxcLobe _3579;
    if (shaped)
    {
        MxcLobe param_4 = l;
        bool param_5 = !reflected;
        _3579 = mxc_ms_lobe(param_4, param_5);
    }
    else
    {
        _3579 = l;
    }
    MxcLobe m = _3579;
    MxcLobe param_6 = m;
    float3 param_7 = o;
    float3 param_8 = float3(u.xy, fast::min(uz, 0.999999940395355224609375));
    MxcLobeSample ls = mxc_lobe_sample(param_6, param_7, param_8);
    if (!bool(ls.valid))
    {
        return s;
    }
    float3x3 param_9 = frame;
    float3 param_10 = ls.wi;
    s.wi = mxc_to_world(param_9, param_10);
    if (bool(ls.delta))
    {
        s.delta = short(true);
        s.pdf = (ls.pdf * p) / total;
        MxcLobe param_11 = l;
        float param_12 = abs(ls.wi.z);
        s.weight = (((l.weight * c.ms[chosen]) * mxc_lobe_absorption(param_11, param_12)) * ls.value) / float3(s.pdf);
        s.valid = short(s.pdf > 0.0);
        return s;
    }
    s.evaluate = short(true);
    s.valid = short(true);
    return s;
}

static inline __attribute__((always_inline))
float3 mxc_exit_direction(thread const float3& d, thread const float3& t)
{
    float3 axis = cross(d, t);
    float s = length(axis);
    if (s < 9.9999999747524270787835121154785e-07)
    {
        return t;
    }
    axis /= float3(s);
    float c = dot(d, t);
    return ((t * c) + (cross(axis, t) * s)) + ((axis * dot(axis, t)) * (1.0 - c));
}

static inline __attribute__((always_inline))
float3 mxc_sky(thread const float3& d)
{
    float y = fast::clamp(d.y, -1.0, 1.0);
    float3 horizon = float3(1.0, 0.959999978542327880859375, 0.89999997615814208984375);
    float3 zenith = float3(0.300000011920928955078125, 0.5, 0.949999988079071044921875);
    float3 ground = float3(0.1599999964237213134765625, 0.14499999582767486572265625, 0.12999999523162841796875);
    if (y >= 0.0)
    {
        return mix(horizon, zenith, float3(sqrt(y)));
    }
    return mix(horizon, ground, float3(sqrt(-y)));
}

static inline __attribute__((always_inline))
float3 mxc_env_to_map(thread const float3& w, thread const float& angle)
{
    float c = cos(angle);
    float s = sin(angle);
    return float3((c * w.x) - (s * w.z), w.y, (s * w.x) + (c * w.z));
}

static inline __attribute__((always_inline))
float2 mxc_env_uv(thread const float3& d)
{
    float _3874;
    if ((abs(d.x) + abs(d.z)) > 9.9999999600419720025001879548654e-13)
    {
        _3874 = 0.5 + (precise::atan2(d.x, -d.z) * 0.15915493667125701904296875);
    }
    else
    {
        _3874 = 0.5;
    }
    float u = _3874;
    float v = precise::atan2(length(d.xz), d.y) * 0.3183098733425140380859375;
    return float2(u, v);
}

static inline __attribute__((always_inline))
float3 mxc_env_lookup(thread const float3& d, texture2d<float> mxc_env_radiance, sampler mxc_env_radianceSmplr)
{
    float3 param = d;
    return mxc_env_radiance.sample(mxc_env_radianceSmplr, mxc_env_uv(param), level(0.0)).xyz;
}

static inline __attribute__((always_inline))
float3 mxc_environment(thread const float3& d, constant MxcView& mxc_view, texture2d<float> mxc_env_radiance, sampler mxc_env_radianceSmplr)
{
    int code = mxc_environment_code(mxc_view);
    if (code == 1)
    {
        return float3(mxc_view.environment.x);
    }
    if (code == 2)
    {
        float3 param = d;
        return mxc_sky(param) * mxc_view.environment.x;
    }
    if (code == 3)
    {
        float3 param_1 = d;
        float param_2 = mxc_view.environment.z;
        float3 param_3 = mxc_env_to_map(param_1, param_2);
        return mxc_env_lookup(param_3, mxc_env_radiance, mxc_env_radianceSmplr) * mxc_view.environment.x;
    }
    return float3(0.0);
}

static inline __attribute__((always_inline))
uint mxc_env_cell(thread const float3& d, const device MxcEnvDistribution& v_208)
{
    float3 param = d;
    float2 uv = mxc_env_uv(param);
    uint2 size = max(v_208.mxc_env_size.xy, uint2(1u));
    uint i = min(uint(fast::max(uv.x, 0.0) * float(size.x)), (size.x - 1u));
    uint j = min(uint(fast::max(uv.y, 0.0) * float(size.y)), (size.y - 1u));
    return (j * size.x) + i;
}

static inline __attribute__((always_inline))
float mxc_env_pdf(thread const float3& d, const device MxcEnvDistribution& v_208)
{
    float3 param = d;
    return ((device float*)&v_208.mxc_env_cells[mxc_env_cell(param, v_208)])[2u];
}

static inline __attribute__((always_inline))
float mxc_power_heuristic(thread const float& a, thread const float& b)
{
    float a2 = a * a;
    float b2 = b * b;
    float _4264;
    if ((a2 + b2) > 0.0)
    {
        _4264 = a2 / (a2 + b2);
    }
    else
    {
        _4264 = 0.0;
    }
    return _4264;
}

static inline __attribute__((always_inline))
float3 mxc_env_sample(thread const float4& u, thread float& pdf, const device MxcEnvDistribution& v_208)
{
    uint2 size = max(v_208.mxc_env_size.xy, uint2(1u));
    uint n = size.x * size.y;
    uint k = min(uint(u.x * float(n)), (n - 1u));
    float4 cell = v_208.mxc_env_cells[k];
    if (u.y >= cell.x)
    {
        k = min(as_type<uint>(cell.y), (n - 1u));
    }
    pdf = ((device float*)&v_208.mxc_env_cells[k])[2u];
    uint i = k % size.x;
    uint j = k / size.x;
    float phi = 6.283185482025146484375 * (((float(i) + u.z) / float(size.x)) - 0.5);
    float y0 = cos((3.1415927410125732421875 * float(j)) / float(size.y));
    float y1 = cos((3.1415927410125732421875 * float(j + 1u)) / float(size.y));
    float y = mix(y0, y1, u.w);
    float param = 1.0 - (y * y);
    float r = mxc_safe_sqrt(param);
    return float3(r * sin(phi), y, (-r) * cos(phi));
}

static inline __attribute__((always_inline))
float3 mxc_env_to_world(thread const float3& m, thread const float& angle)
{
    float c = cos(angle);
    float s = sin(angle);
    return float3((c * m.x) + (s * m.z), m.y, ((-s) * m.x) + (c * m.z));
}

static inline __attribute__((always_inline))
float3 mxc_closure_eval_pdf(thread const MxcClosure& c, thread const float3& wo, thread const float3& wi, thread const bool& wantPdf, thread float& pdf)
{
    float3 f = float3(0.0);
    float p = 0.0;
    MxcLobe _3357;
    float3 _3361;
    float3 _3362;
    float3 _3363;
    float _3368;
    float _3369;
    for (int k = 0; k < c.count; k++)
    {
        MxcLobe l = c.lobes[k];
        if (all(l.weight == float3(0.0)))
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
        float3 fk = float3(0.0);
        float pk = 0.0;
        int passes = (c.msPick[k] > 0.0) ? 2 : 1;
        for (int pass = 0; pass < passes; pass++)
        {
            bool shaped = pass == 1;
            if (shaped)
            {
                MxcLobe param_6 = l;
                bool param_7 = i.z < 0.0;
                _3357 = mxc_ms_lobe(param_6, param_7);
            }
            else
            {
                _3357 = l;
            }
            MxcLobe m = _3357;
            if (shaped)
            {
                if (i.z > 0.0)
                {
                    _3362 = c.msLobe[k];
                }
                else
                {
                    _3362 = c.msLobeT[k];
                }
                _3361 = _3362;
            }
            else
            {
                if ((o.z * i.z) < 0.0)
                {
                    _3363 = float3(c.msT[k]);
                }
                else
                {
                    _3363 = c.ms[k];
                }
                _3361 = _3363;
            }
            float3 scale = _3361;
            MxcLobe param_8 = m;
            float3 param_9 = o;
            float3 param_10 = i;
            fk += (scale * mxc_lobe_eval(param_8, param_9, param_10));
            if (wantPdf)
            {
                if (shaped)
                {
                    if (i.z > 0.0)
                    {
                        _3369 = c.msSplit[k];
                    }
                    else
                    {
                        _3369 = 1.0 - c.msSplit[k];
                    }
                    _3368 = c.msPick[k] * _3369;
                }
                else
                {
                    _3368 = 1.0 - c.msPick[k];
                }
                float share = _3368;
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
    float _3375;
    if (c.choiceTotal > 0.0)
    {
        _3375 = p / c.choiceTotal;
    }
    else
    {
        _3375 = 0.0;
    }
    pdf = _3375;
    return f;
}

fragment main0_out main0(main0_in in [[stage_in]], constant MxcView& mxc_view [[buffer(0)]], const device MxcParameters& mxc_params [[buffer(1)]], const device MxcEnvDistribution& v_208 [[buffer(2)]], texture2d<float> mxc_tables [[texture(0)]], texture2d<float> mxc_env_radiance [[texture(1)]], sampler mxc_tablesSmplr [[sampler(0)]], sampler mxc_env_radianceSmplr [[sampler(1)]], bool gl_FrontFacing [[front_facing]], float4 gl_FragCoord [[position]])
{
    main0_out out = {};
    MxcGeometry g;
    g.P = in.vPosition;
    g.Pobj = in.vObjectPosition;
    float3 param = in.vNormal;
    float3 param_1 = float3(0.0, 0.0, 1.0);
    float3 N = mxc_safe_normalize(param, param_1);
    if (!gl_FrontFacing)
    {
        N = -N;
    }
    float3 param_2 = mxc_view.eye.xyz - in.vPosition;
    float3 param_3 = N;
    float3 wo = mxc_safe_normalize(param_2, param_3);
    float facing = dot(wo, N);
    if (facing < 0.00999999977648258209228515625)
    {
        N = fast::normalize(N + (wo * (0.00999999977648258209228515625 - facing)));
    }
    float handedness = (in.vTangent.w < 0.0) ? (-1.0) : 1.0;
    float3 param_4 = N;
    float3 param_5 = in.vTangent.xyz;
    float3x3 frame = mxc_frame(param_4, param_5);
    g.N = N;
    g.T = frame[0];
    g.B = frame[1] * handedness;
    float3 param_6 = in.vObjectNormal;
    float3 param_7 = float3(0.0, 0.0, 1.0);
    g.Nobj = mxc_safe_normalize(param_6, param_7);
    float3 param_8 = g.Nobj;
    float3 param_9 = in.vObjectTangent;
    float3x3 objectFrame = mxc_frame(param_8, param_9);
    g.Tobj = objectFrame[0];
    g.Bobj = objectFrame[1] * handedness;
    g.uv = in.vUv;
    g.color = float4(1.0);
    g.objectToWorld = mxc_view.objectToWorld;
    g.frame = mxc_params.frame;
    g.time = mxc_params.time;
    uint param_10 = uint(mxc_view.counts.z) + 7u;
    uint param_11 = uint(gl_FragCoord.y) + mxc_pcg(param_10);
    uint param_12 = uint(gl_FragCoord.x) ^ mxc_pcg(param_11);
    uint param_13 = mxc_pcg(param_12);
    mxc_closure_seed(param_13);
    MxcGeometry param_14 = g;
    float3 param_15 = wo;
    MxcClosure param_16;
    mxc_material_closure(param_14, param_15, param_16, mxc_tables, mxc_tablesSmplr);
    MxcClosure c = param_16;
    float3 radiance = c.emission * mxc_view.environment.y;
    int lights = mxc_light_count(mxc_view);
    int kinds = mxc_light_kinds();
    bool image = mxc_environment_code(mxc_view) == 3;
    int _264;
    if (mxc_environment_code(mxc_view) != 0)
    {
        _264 = max(mxc_view.counts.w, 1);
    }
    else
    {
        _264 = 0;
    }
    int n = _264;
    uint param_17 = uint(mxc_view.counts.z);
    uint param_18 = uint(gl_FragCoord.y) + mxc_pcg(param_17);
    uint param_19 = uint(gl_FragCoord.x) + mxc_pcg(param_18);
    uint seed = mxc_pcg(param_19);
    uint param_20 = uint(gl_FragCoord.y) + 2654435769u;
    uint param_21 = uint(gl_FragCoord.x) ^ mxc_pcg(param_20);
    uint pixel = mxc_pcg(param_21);
    uint param_22 = pixel;
    float _505 = mxc_uniform(param_22);
    pixel = param_22;
    uint param_23 = pixel;
    float _509 = mxc_uniform(param_23);
    pixel = param_23;
    uint param_24 = pixel;
    float _512 = mxc_uniform(param_24);
    pixel = param_24;
    uint param_25 = pixel;
    float _515 = mxc_uniform(param_25);
    pixel = param_25;
    float4 shift = float4(_505, _509, _512, _515);
    float3 sum = float3(0.0);
    int _281;
    MxcSample smp;
    float3 _298;
    float3 _299;
    float _304;
    float param_49;
    int _328;
    float param_59;
    float _344;
    for (int b = 0; b < max(n, int(lights > 0)); b++)
    {
        int batchLights = (b == 0) ? lights : 0;
        if (b < n)
        {
            _281 = 1 + int(image);
        }
        else
        {
            _281 = 0;
        }
        int batchSamples = _281;
        uint index = (uint(mxc_view.counts.z) * uint(max(n, 1))) + uint(b);
        uint param_26 = index;
        uint param_27 = 2u;
        float _555 = mxc_radical_inverse(param_26, param_27);
        uint param_28 = index;
        uint param_29 = 3u;
        float _558 = mxc_radical_inverse(param_28, param_29);
        uint param_30 = index;
        uint param_31 = 5u;
        float _560 = mxc_radical_inverse(param_30, param_31);
        uint param_32 = index;
        uint param_33 = 7u;
        float _562 = mxc_radical_inverse(param_32, param_33);
        float4 choice = fract(float4(_555, _558, _560, _562) + shift);
        smp.valid = short(false);
        smp.evaluate = short(false);
        smp.delta = short(false);
        smp.pdf = 0.0;
        smp.weight = float3(0.0);
        smp.wi = N;
        if (n > 0)
        {
            MxcClosure param_34 = c;
            float3 param_35 = wo;
            float3 param_36 = float3(choice.z, choice.w, choice.x);
            smp = mxc_closure_sample_direction(param_34, param_35, param_36);
        }
        bool above = dot(smp.wi, N) > 0.0;
        if (bool(smp.valid))
        {
            if (above)
            {
                _299 = smp.wi;
            }
            else
            {
                float3 param_37 = -wo;
                float3 param_38 = smp.wi;
                _299 = mxc_exit_direction(param_37, param_38);
            }
            float3 param_39 = _299;
            _298 = mxc_environment(param_39, mxc_view, mxc_env_radiance, mxc_env_radianceSmplr);
        }
        else
        {
            _298 = float3(0.0);
        }
        float3 seen = _298;
        bool _620 = (b < n) && bool(smp.valid);
        bool _626;
        if (_620)
        {
            _626 = !bool(smp.evaluate);
        }
        else
        {
            _626 = _620;
        }
        if (_626)
        {
            bool _631 = image && above;
            bool _637;
            if (_631)
            {
                _637 = !bool(smp.delta);
            }
            else
            {
                _637 = _631;
            }
            if (_637)
            {
                float3 param_40 = smp.wi;
                float param_41 = mxc_view.environment.z;
                float3 param_42 = mxc_env_to_map(param_40, param_41);
                float param_43 = smp.pdf;
                float param_44 = mxc_env_pdf(param_42, v_208);
                _304 = mxc_power_heuristic(param_43, param_44);
            }
            else
            {
                _304 = 1.0;
            }
            float w = _304;
            sum += ((smp.weight * w) * seen);
        }
        float3 m = float3(0.0);
        float lightPdf = 0.0;
        float3 imageWi = N;
        float3 imageSeen = float3(0.0);
        if (image && (b < n))
        {
            uint param_45 = seed;
            float _673 = mxc_uniform(param_45);
            seed = param_45;
            uint param_46 = seed;
            float _676 = mxc_uniform(param_46);
            seed = param_46;
            uint param_47 = seed;
            float _679 = mxc_uniform(param_47);
            seed = param_47;
            float4 v = float4(choice.y, _673, _676, _679);
            float4 param_48 = v;
            float3 _683 = mxc_env_sample(param_48, param_49, v_208);
            lightPdf = param_49;
            m = _683;
            float3 param_50 = m;
            float param_51 = mxc_view.environment.z;
            imageWi = mxc_env_to_world(param_50, param_51);
            bool _692 = lightPdf > 0.0;
            bool _699;
            if (_692)
            {
                _699 = dot(imageWi, N) > 0.0;
            }
            else
            {
                _699 = _692;
            }
            if (_699)
            {
                float3 param_52 = imageWi;
                imageSeen = mxc_environment(param_52, mxc_view, mxc_env_radiance, mxc_env_radianceSmplr);
            }
        }
        for (int j = 0; j < (batchLights + batchSamples); j++)
        {
            float3 wi = N;
            float3 incoming = float3(0.0);
            bool use = true;
            if ((n == 0) || (j < batchLights))
            {
                _328 = 0;
            }
            else
            {
                _328 = (j == ((batchLights + 1) - 1)) ? 1 : 2;
            }
            int strategy = _328;
            if (strategy == 0)
            {
                float4 light = mxc_view.lightVector[j];
                incoming = mxc_view.lightRadiance[j].xyz;
                bool _744 = kinds == 1;
                bool _757;
                if (!_744)
                {
                    bool _750 = (kinds & 1) != 0;
                    bool _756;
                    if (_750)
                    {
                        _756 = light.w == 0.0;
                    }
                    else
                    {
                        _756 = _750;
                    }
                    _757 = _756;
                }
                else
                {
                    _757 = _744;
                }
                bool directional = _757;
                if (directional)
                {
                    float3 param_53 = light.xyz;
                    float3 param_54 = N;
                    wi = mxc_safe_normalize(param_53, param_54);
                }
                else
                {
                    float3 d = light.xyz - in.vPosition;
                    float d2 = fast::max(dot(d, d), 9.9999999392252902907785028219223e-09);
                    wi = d * rsqrt(d2);
                    incoming /= float3(d2);
                    bool _784 = (kinds & 4) != 0;
                    bool _790;
                    if (_784)
                    {
                        _790 = light.w == 2.0;
                    }
                    else
                    {
                        _790 = _784;
                    }
                    if (_790)
                    {
                        float4 spot = mxc_view.lightSpot[j];
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
                    use = bool(smp.valid) && bool(smp.evaluate);
                }
                else
                {
                    wi = imageWi;
                    incoming = imageSeen;
                    bool _825 = lightPdf > 0.0;
                    bool _832;
                    if (_825)
                    {
                        _832 = dot(imageWi, N) > 0.0;
                    }
                    else
                    {
                        _832 = _825;
                    }
                    use = _832;
                }
            }
            MxcClosure param_55 = c;
            float3 param_56 = wo;
            float3 param_57 = wi;
            bool param_58 = strategy != 0;
            float3 _838 = mxc_closure_eval_pdf(param_55, param_56, param_57, param_58, param_59);
            float pdf = param_59;
            float3 f = _838;
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
                            float3 param_60 = wi;
                            float param_61 = mxc_view.environment.z;
                            float3 param_62 = mxc_env_to_map(param_60, param_61);
                            float param_63 = pdf;
                            float param_64 = mxc_env_pdf(param_62, v_208);
                            _344 = mxc_power_heuristic(param_63, param_64);
                        }
                        else
                        {
                            _344 = 1.0;
                        }
                        float w_1 = _344;
                        sum += (((f * w_1) / float3(pdf)) * incoming);
                    }
                }
                else
                {
                    if (use)
                    {
                        float3 param_65 = m;
                        float param_66 = mxc_env_pdf(param_65, v_208);
                        float param_67 = pdf;
                        float w_2 = mxc_power_heuristic(param_66, param_67);
                        sum += (((f * w_2) * incoming) / float3(lightPdf));
                    }
                }
            }
        }
    }
    radiance += (sum / float3(float(max(n, 1))));
    float3 param_68 = c.transparency;
    float coverage = 1.0 - fast::clamp(mxc_luminance(param_68), 0.0, 1.0);
    out.outColor = float4(radiance, coverage);
    return out;
}

// ==== vertex (main0) ====
#pragma clang diagnostic ignored "-Wmissing-prototypes"

#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

template<typename T>
[[clang::optnone]] T spvFMul(T l, T r)
{
    return fma(l, r, T(0));
}

template<typename T, int Cols, int Rows>
[[clang::optnone]] vec<T, Cols> spvFMulVectorMatrix(vec<T, Rows> v, matrix<T, Cols, Rows> m)
{
    vec<T, Cols> res = vec<T, Cols>(0);
    for (uint i = Rows; i > 0; --i)
    {
        vec<T, Cols> tmp(0);
        for (uint j = 0; j < Cols; ++j)
        {
            tmp[j] = m[j][i - 1];
        }
        res = fma(tmp, vec<T, Cols>(v[i - 1]), res);
    }
    return res;
}

template<typename T, int Cols, int Rows>
[[clang::optnone]] vec<T, Rows> spvFMulMatrixVector(matrix<T, Cols, Rows> m, vec<T, Cols> v)
{
    vec<T, Rows> res = vec<T, Rows>(0);
    for (uint i = Cols; i > 0; --i)
    {
        res = fma(m[i - 1], vec<T, Rows>(v[i - 1]), res);
    }
    return res;
}

template<typename T, int LCols, int LRows, int RCols, int RRows>
[[clang::optnone]] matrix<T, RCols, LRows> spvFMulMatrixMatrix(matrix<T, LCols, LRows> l, matrix<T, RCols, RRows> r)
{
    matrix<T, RCols, LRows> res;
    for (uint i = 0; i < RCols; i++)
    {
        vec<T, RCols> tmp(0);
        for (uint j = 0; j < LCols; j++)
        {
            tmp = fma(vec<T, RCols>(r[i][j]), l[j], tmp);
        }
        res[i] = tmp;
    }
    return res;
}

template<typename T>
[[clang::optnone]] T spvFAdd(T l, T r)
{
    return fma(T(1), l, r);
}

struct MxcView
{
    float4x4 objectToWorld;
    float4x4 normalToWorld;
    float4x4 worldToClip;
    float4 eye;
    float4 jitter;
    float4 lightVector[8];
    float4 lightSpot[8];
    float4 lightRadiance[8];
    int4 counts;
    float4 environment;
};

constant int MXC_ENVIRONMENT_tmp [[function_constant(0)]];
constant int MXC_ENVIRONMENT = is_function_constant_defined(MXC_ENVIRONMENT_tmp) ? MXC_ENVIRONMENT_tmp : -1;
constant int MXC_LIGHT_COUNT_tmp [[function_constant(1)]];
constant int MXC_LIGHT_COUNT = is_function_constant_defined(MXC_LIGHT_COUNT_tmp) ? MXC_LIGHT_COUNT_tmp : -1;
constant int MXC_LIGHT_KINDS_tmp [[function_constant(2)]];
constant int MXC_LIGHT_KINDS = is_function_constant_defined(MXC_LIGHT_KINDS_tmp) ? MXC_LIGHT_KINDS_tmp : -1;

struct main0_out
{
    float3 vPosition [[user(locn0)]];
    float3 vNormal [[user(locn1)]];
    float4 vTangent [[user(locn2)]];
    float2 vUv [[user(locn3)]];
    float3 vObjectPosition [[user(locn4)]];
    float3 vObjectNormal [[user(locn5)]];
    float3 vObjectTangent [[user(locn6)]];
    float4 gl_Position [[position]];
};

struct main0_in
{
    float3 inPosition [[attribute(0)]];
    float3 inNormal [[attribute(1)]];
    float4 inTangent [[attribute(2)]];
    float2 inUv [[attribute(3)]];
};

vertex main0_out main0(main0_in in [[stage_in]], constant MxcView& mxc_view [[buffer(0)]])
{
    main0_out out = {};
    float4 world = spvFMulMatrixVector(mxc_view.objectToWorld, float4(in.inPosition, 1.0));
    out.vPosition = world.xyz;
    out.vNormal = float3x3(mxc_view.normalToWorld[0].xyz, mxc_view.normalToWorld[1].xyz, mxc_view.normalToWorld[2].xyz) * in.inNormal;
    out.vTangent = float4(float3x3(mxc_view.objectToWorld[0].xyz, mxc_view.objectToWorld[1].xyz, mxc_view.objectToWorld[2].xyz) * in.inTangent.xyz, in.inTangent.w);
    out.vUv = in.inUv;
    out.vObjectPosition = in.inPosition;
    out.vObjectNormal = in.inNormal;
    out.vObjectTangent = in.inTangent.xyz;
    float4 clip = spvFMulMatrixVector(mxc_view.worldToClip, world);
    float _104 = clip.w;
    float4 _106 = clip;
    float2 _108 = spvFAdd(_106.xy, mxc_view.jitter.xy * _104);
    clip.x = _108.x;
    clip.y = _108.y;
    out.gl_Position = clip;
    return out;
}

