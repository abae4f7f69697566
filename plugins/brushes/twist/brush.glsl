// Rotates each sample about the axis through the centre along the centre normal by the angle
// times its weight (Rodrigues' formula): its distance from the axis and its height along it stay.
vec4 brush(vec4 value, BrushInput b) {
  vec3 n = u_centreNormal;
  vec3 rel = value.xyz - u_centre;
  float a = radians(u_angle) * b.weight;
  float c = cos(a), s = sin(a);
  vec3 turned = rel * c + cross(n, rel) * s + n * (dot(n, rel) * (1.0 - c));
  return vec4(u_centre + turned, value.w);
}
