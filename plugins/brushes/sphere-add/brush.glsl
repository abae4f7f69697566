// Closed form of the thesis's stepping dimple: the sphere (radius half the brush radius, so it
// stays inside the brush's reach) sits along the centre normal so that it cuts the surface
// strength × its radius deep; every sample inside it moves to the nearest point of its surface.
vec4 brush(vec4 value, BrushInput b) {
  float sphereRadius = 0.5 * u_radius;
  float depth = clamp(abs(u_strength * u_pressure), 0.0, 1.0) * sphereRadius;
  vec3 sphereCentre = u_centre - u_centreNormal * (sphereRadius - depth);
  vec3 offset = value.xyz - sphereCentre;
  float distance = length(offset);
  if (distance >= sphereRadius || distance == 0.0) return value;
  vec3 onSphere = sphereCentre + offset * (sphereRadius / distance);
  return vec4(mix(value.xyz, onSphere, maskAt(b.texel)), value.w);
}
