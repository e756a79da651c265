// OpenPBR "Subsurface" in the albedo-scaling tiers: the semi-infinite scattering medium under
// the base's interface (and a coat) as a diffuse lobe of the observed colour C, with the
// angular dependence and the coat's darkening that the medium's own transport gives it. The
// reference walk (mxc_walk.glsl) follows light through the medium instead; this is the
// half-space's transport in closed form, which that walk bears out (issue 39).

#ifndef MXC_ACCURACY_FAST
// The 4-point Gauss-Legendre rule on [0, 1]: nodes (interior, > 0) and weights (summing to 1).
const vec4 MXC_GAUSS4_X = vec4(0.0694318, 0.3300095, 0.6699905, 0.9305682);
const vec4 MXC_GAUSS4_W = vec4(0.1739274, 0.3260726, 0.3260726, 0.1739274);

// Chandrasekhar's H-function of an isotropic half-space, in the approximation
// H(mu) = (1 + 2 mu) / (1 + 2 s mu) (Hapke 1981, eq. 10; within about 3% of the exact H), with
// s = sqrt(1 - omega), or van de Hulst's sqrt((1 - omega) / (1 - omega g)) for an anisotropic
// medium (the similarity relation). Its albedo for light incident at mu is then
// A(mu) = 1 - s H(mu) = (1 - s) / (1 + 2 s mu) (Chandrasekhar 1960, s. 47).
vec3 mxc_hapke_h(vec3 s, float mu) { return vec3(1.0 + 2.0 * mu) / (1.0 + 2.0 * s * mu); }  // s, mu >= 0: >= 1
vec3 mxc_hapke_albedo(vec3 s, float mu) { return (1.0 - s) / (1.0 + 2.0 * s * mu); }

// The stack over a half-space of IOR eta_m (relative to the outermost medium): the edge of its
// escape cone, mu_c = sqrt(1 - 1 / eta_m^2) (0 when eta_m <= 1: nothing is totally reflected),
// and its transmittance towards the outermost medium at the cone's quadrature nodes
// mu = mu_c + (1 - mu_c) x_k, for a ray with x = eta_m sin(theta) < 1 (the invariant of parallel
// interfaces): through the medium's interface alone (eta_c <= 1), or through a coat of IOR eta_c
// over it with the two interfaces' reflections summed incoherently, (1 - F_m)(1 - F_c) /
// (1 - F_m F_c). Each Fresnel factor is taken on the side where the ray's angle is known; it is
// the same on both sides (Stokes' relations).
struct MxcHalfSpaceStack {
  float muc;
  vec4 t;
};
MxcHalfSpaceStack mxc_halfspace_stack(float eta_m, float eta_c) {
  MxcHalfSpaceStack h;
  h.muc = mxc_safe_sqrt(1.0 - 1.0 / max(eta_m * eta_m, 1.0));
  float em = max(eta_m, 1e-3);
  for (int k = 0; k < 4; ++k) {
    float mu = h.muc + (1.0 - h.muc) * MXC_GAUSS4_X[k];
    float x = min(em * mxc_safe_sqrt(1.0 - mu * mu), 1.0);
    float cosOut = mxc_safe_sqrt(1.0 - x * x);
    if (eta_c <= 1.0) {
      h.t[k] = 1.0 - mxc_fresnel_dielectric(cosOut, em);
    } else {
      float fc = mxc_fresnel_dielectric(cosOut, eta_c);
      float fm = mxc_fresnel_dielectric(mxc_safe_sqrt(1.0 - x * x / (eta_c * eta_c)), em / eta_c);  // eta_c > 1
      h.t[k] = (1.0 - fm) * (1.0 - fc) / max(1.0 - fm * fc, 1e-6);  // fm, fc < 1 inside the cone: > 0
    }
  }
  return h;
}

// What a half-space (van de Hulst's s per channel) returns out of the stack above it, per unit
// flux entering it along a direction of cosine muT in the medium. It reflects A(muT); the light
// it sends back up has the angular density mu H(mu) / (mu + mu0) of a half-space lit from mu0
// (Chandrasekhar 1960, s. 47); of it the stack lets out what lies in the escape cone, times its
// transmittance: e(mu0). The rest (totally reflected outside the cone, reflected inside it)
// comes back in along the same angles, where the medium returns A_g of it, the mean of A over
// them; and so on:
//   out = A(muT) (e1 + (1 - e1) A_g e_g / (1 - A_g (1 - e_g))),
// e1 = e(muT), e_g = e for light from the middle of the trapped directions (a fixed angle is
// enough: the density hardly depends on mu0 there). The integrals are 4-point Gauss-Legendre on
// each side of the cone's edge. Against a discrete-ordinates solution of the same transport with
// the exact H (200 directions), the closed form is within 0.005 for C = 0.2 to 0.95 under coats
// of IOR 1.5 to 2 over media of 1.33 to 1.5; that solution is the reference walk's pearl under
// its coat within 0.002 (0.669, 0.602, 0.541 against 0.668, 0.600, 0.541).
vec3 mxc_halfspace_return(vec3 s, float muT, MxcHalfSpaceStack stack) {
  float muc = stack.muc;
  float mu0g = 0.5 * muc;
  vec3 escapedFirst = vec3(0.0), allFirst = vec3(0.0), escapedGrazing = vec3(0.0), allGrazing = vec3(0.0);
  vec3 back = vec3(0.0), backReturned = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    // Inside the cone (mu > 0: the nodes are interior).
    float mu = muc + (1.0 - muc) * MXC_GAUSS4_X[k];
    vec3 h = mu * mxc_hapke_h(s, mu) * ((1.0 - muc) * MXC_GAUSS4_W[k]);
    float t = stack.t[k];
    vec3 first = h / (mu + muT);
    vec3 grazing = h / (mu + mu0g);
    escapedFirst += first * t;
    allFirst += first;
    escapedGrazing += grazing * t;
    allGrazing += grazing;
    back += first * (1.0 - t);
    backReturned += first * (1.0 - t) * mxc_hapke_albedo(s, mu);
    // Outside it (mu = h = 0 when nothing is trapped: the floors only avoid 0 / 0).
    mu = muc * MXC_GAUSS4_X[k];
    h = mu * mxc_hapke_h(s, mu) * (muc * MXC_GAUSS4_W[k]);
    first = h / max(mu + muT, 1e-6);
    allFirst += first;
    allGrazing += h / max(mu + mu0g, 1e-6);
    back += first;
    backReturned += first * mxc_hapke_albedo(s, mu);
  }
  // The sums over all directions are > 0 (the escaping nodes' alone are); A_g <= 1 - s < 1
  // unless s = 0, where e_g > 0 keeps the last denominator > 0.
  vec3 e1 = escapedFirst / allFirst;
  vec3 eg = escapedGrazing / allGrazing;
  vec3 ag = backReturned / max(back, vec3(1e-12));
  return mxc_hapke_albedo(s, clamp(muT, 0.0, 1.0)) * (e1 + (1.0 - e1) * ag * eg / max(1.0 - ag * (1.0 - eg), vec3(1e-4)));
}

// The s with which the half-space returns C per unit flux entering it at normal incidence
// through `stack` (its observed colour, eq. subsurface_albedo_constraint), and in `returned`
// what that s returns there. The return falls with s as the index-matched albedo
// A(1) = (1 - s) / (1 + 2 s) does, whose inverse is s = (1 - A) / (1 + 2 A): starting from that
// of C, each step scales s by the ratio of that inverse at C to its value at what s returns.
// Three steps: within 0.001 of C for C >= 0.5 and within 0.005 below it, IORs 1 to 2 (the first
// step does most of it); the caller divides by `returned`, so that the observed colour at
// normal incidence is C exactly whatever is left. C is clamped to [1e-3, 0.999]: s in (0, 1).
vec3 mxc_halfspace_s(vec3 C, MxcHalfSpaceStack stack, out vec3 returned) {
  vec3 c = clamp(C, vec3(1e-3), vec3(0.999));
  vec3 target = (1.0 - c) / (1.0 + 2.0 * c);
  vec3 s = target;
  returned = mxc_halfspace_return(s, 1.0, stack);
  for (int k = 0; k < 2; ++k) {
    vec3 r = clamp(returned, vec3(1e-4), vec3(0.9999));
    s = clamp(s * target / ((1.0 - r) / (1.0 + 2.0 * r)), vec3(1e-5), vec3(1.0));  // (1 - r) / (1 + 2 r) > 0
    returned = mxc_halfspace_return(s, 1.0, stack);
  }
  return s;
}

// The factor on the observed colour C of the subsurface lobe at the view cosine muO: C times it
// is the lobe's albedo. `eta`: the medium's IOR (specular_ior); `coatIor`, `coatCoverage`: the
// coat above (coverage 0: none); `delta`: its coat_darkening; `applied`: the darkening the
// coat's layering already applies to what is under it (mxc_coat_darkening).
// - Uncoated, C is what the medium returns through its interface at normal incidence (eq.
//   subsurface_albedo_constraint): out(muT) / out(1), 1 at normal incidence, and the
//   half-space's own rise towards grazing views (the walk: 0.809 to 0.862 for pearl's red at 0
//   to 79 degrees, where a Lambertian stays at C).
// - Under a coat, C is what it returns into the coat through its interface (IOR ratio
//   eta / coatIor, as the walk meets it): out through the coat as well, over out into the coat at
//   normal incidence, in place of the darkening of a Lambertian base (coat_darkening 0: through
//   the interface alone). A base less dense than its coat fills only part of the coat with its
//   light, and a half-space sends it up steeper and returns more of what the coat sends back at
//   grazing angles than a Lambertian.
// Partial coverage mixes the two factors by it. For a given C the similarity relation makes the
// factor independent of the medium's anisotropy.
vec3 mxc_subsurface_factor(vec3 C, float eta, float muO, float coatIor, float coatCoverage, float delta, vec3 applied) {
  muO = clamp(muO, 0.0, 1.0);
  float em = max(eta, 1.0);
  float muT = mxc_safe_sqrt(1.0 - (1.0 - muO * muO) / (em * em));  // the view refracted into the medium
  MxcHalfSpaceStack bare = mxc_halfspace_stack(em, 0.0);
  vec3 normal;
  vec3 s = mxc_halfspace_s(C, bare, normal);
  vec3 uncoated = mxc_halfspace_return(s, muT, bare) / max(normal, vec3(1e-6));
  if (coatCoverage <= 0.0) return uncoated;
  float ec = max(coatIor, 1.0);
  MxcHalfSpaceStack fromCoat = mxc_halfspace_stack(em / ec, 0.0);  // seen from the coat
  s = mxc_halfspace_s(C, fromCoat, normal);
  vec3 coated = mxc_halfspace_return(s, muT, fromCoat);
  if (delta > 0.0) coated = mix(coated, mxc_halfspace_return(s, muT, mxc_halfspace_stack(em, ec)), clamp(delta, 0.0, 1.0));
  coated /= max(normal, vec3(1e-6)) * max(applied, vec3(1e-3));  // applied >= 1 - K > 0
  return mix(uncoated, coated, clamp(coatCoverage, 0.0, 1.0));
}
#else
// The fast tier keeps the spec's diffuse lobe of the observed colour ("Flexibility of
// implementation") under the Lambertian darkening.
vec3 mxc_subsurface_factor(vec3 C, float eta, float muO, float coatIor, float coatCoverage, float delta, vec3 applied) {
  return vec3(1.0);
}
#endif
