// Screen-sized dots: anti-aliased disc with a darker rim so it reads on any background.
in vec4 vColor;
in vec2 vOffset;
flat in float vRadius;
out vec4 fragColor;
void main() {
  float r = length(vOffset);
  float coverage = clamp(vRadius + 0.5 - r, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  float rim = smoothstep(vRadius - 2.0, vRadius - 1.0, r);
  vec3 color = mix(vColor.rgb, vColor.rgb * 0.45, rim);
  fragColor = vec4(color, vColor.a * coverage);
}
