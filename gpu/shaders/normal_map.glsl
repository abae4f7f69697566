// Normal-map pass: writes normalAt() of the prelude (the brushes' own normals, seam-aware)
// for every texel in the pass's rectangles. The host prepends the version and layer defines.
out vec4 o_normal;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  o_normal = vec4(normalAt(t) * 0.5 + 0.5, 1.0); // RGBA8: unit vectors mapped to [0, 1]
}
