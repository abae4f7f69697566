// Feature B is the reflectivity; R (height detail) and G (specular) pass through untouched.
vec4 brush(vec4 value, BrushInput b) {
  float w = clamp(b.weight, 0.0, 1.0);
  float target = u_mode == 1 ? u_layerFill.b : u_value;
  value.b = w >= 1.0 ? target : mix(value.b, target, w);
  return value;
}
