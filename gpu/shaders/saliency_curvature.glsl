// Saliency, pass 2: curvature as the change of normal across the sample's neighbourhood, the
// mean of 1 - n·n' over its four grid neighbours read through wrap(). The host prepends the
// version and the prelude (wrapTexel, u_size).
uniform sampler2D u_normals;
out vec4 o_value;

vec3 normalOf(ivec2 s) { return texelFetch(u_normals, wrapTexel(s), 0).xyz; }

void main() {
  ivec2 s = ivec2(gl_FragCoord.xy);
  vec3 n = normalOf(s);
  float change = (1.0 - dot(n, normalOf(s + ivec2(1, 0)))) + (1.0 - dot(n, normalOf(s - ivec2(1, 0)))) +
                 (1.0 - dot(n, normalOf(s + ivec2(0, 1)))) + (1.0 - dot(n, normalOf(s - ivec2(0, 1))));
  o_value = vec4(0.25 * change, 0.0, 0.0, 0.0);
}
