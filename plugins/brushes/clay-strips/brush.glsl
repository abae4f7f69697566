// A square footprint (half side 0.7 radii, inside the brush's sphere) whose sides follow the
// stroke's direction; under it every sample below the plane u_height radii above the centre
// moves towards the plane by the weight, softened over the square's outer 30 %. Samples above
// the plane stay: the strips only add.
vec4 brush(vec4 value, BrushInput b) {
  vec3 n = u_centreNormal;
  vec3 t = u_strokeDirection - n * dot(u_strokeDirection, n);
  if (dot(t, t) < 1e-12) t = cross(n, abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0));
  t = normalize(t);
  vec3 s = cross(n, t);
  vec3 rel = value.xyz - u_centre;
  float e = max(abs(dot(rel, t)), abs(dot(rel, s))) / (0.7 * u_radius);
  if (e >= 1.0) return value;
  float below = dot(rel, n) - u_height * u_radius;
  if (below >= 0.0) return value;
  float w = clamp(b.weight, 0.0, 1.0) * (1.0 - smoothstep(0.7, 1.0, e));
  return vec4(value.xyz - n * (below * w), value.w);
}
