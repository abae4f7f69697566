// Normal-map pass: writes normalAt() of the prelude (the brushes' own normals, seam-aware)
// for every texel in the pass's rectangles. The host prepends the version and layer defines.
// Where the samples crumple (the image stretched so far that neighbouring cells fold against
// each other, though the surface is smooth a few samples across) that one-ring normal is noise
// and shades as speckles; there a wider stencil's normal takes over.
out vec4 o_normal;

vec3 centralNormal(ivec2 t, int r) {
  vec3 du = fetchPositions(t + ivec2(r, 0)).xyz - fetchPositions(t - ivec2(r, 0)).xyz;
  vec3 dv = fetchPositions(t + ivec2(0, r)).xyz - fetchPositions(t - ivec2(0, r)).xyz;
  return cross(du, dv);
}

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec3 n = normalAt(t);
  // How well the four cells around the sample agree: 1 on a smooth surface, about 0 where they
  // fold over each other.
  vec3 p = fetchPositions(t).xyz;
  vec3 e[4] = vec3[4](fetchPositions(t + ivec2(1, 0)).xyz - p,
                      fetchPositions(t + ivec2(0, 1)).xyz - p,
                      fetchPositions(t - ivec2(1, 0)).xyz - p,
                      fetchPositions(t - ivec2(0, 1)).xyz - p);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    vec3 q = cross(e[k], e[(k + 1) % 4]);
    if (dot(q, q) > 1e-30) sum += normalize(q);
  }
  float agreement = length(sum) * 0.25;
  if (agreement < 0.8) {
    vec3 wide = centralNormal(t, 2) + centralNormal(t, 3);
    if (dot(wide, wide) > 1e-30)
      n = normalize(mix(normalize(wide), n, smoothstep(0.4, 0.8, agreement)));
  }
  o_normal = vec4(n * 0.5 + 0.5, 1.0); // RGBA8: unit vectors mapped to [0, 1]
}
