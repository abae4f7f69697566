// main() of every brush pass: texels outside the brush's area keep their value bit-exactly.
out vec4 o_value;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 value = texelFetch(u_layer, t, 0);
  BrushInput b = brushInputAt(t, value);
  o_value = b.weight != 0.0 ? brush(value, b) : value; // negative weights pull
}
