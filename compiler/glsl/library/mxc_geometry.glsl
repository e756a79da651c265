// The shading point the generated material reads: positions, frame and texture coordinates in
// the spaces MaterialX's geometric properties name (Pworld, Nobject, UV0, ...).

struct MxcGeometry {
  vec3 P;       // world position
  vec3 Pobj;    // object position
  vec3 N;       // world shading normal (unit)
  vec3 Nobj;    // object normal (unit)
  vec3 T;       // world tangent (unit)
  vec3 Tobj;
  vec3 B;       // world bitangent (unit)
  vec3 Bobj;
  vec2 uv;      // texture coordinates, set 0
  vec4 color;   // vertex colour, set 0
  mat4 objectToWorld;
  float frame;  // application frame number
  float time;   // application time (seconds)
};

// A point, vector or normal between "object" (or "model") and "world" space.
vec3 mxc_transform(MxcGeometry g, vec3 v, int kind, bool toWorld) {
  mat4 m = toWorld ? g.objectToWorld : inverse(g.objectToWorld);  // an affine transform: invertible
  if (kind == MXC_TRANSFORM_POINT) return (m * vec4(v, 1.0)).xyz;
  if (kind == MXC_TRANSFORM_VECTOR) return mat3(m) * v;
  // Normals by the inverse transpose; the result is renormalised (a zero stays zero).
  return mxc_safe_normalize(transpose(inverse(mat3(m))) * v, vec3(0.0));
}
