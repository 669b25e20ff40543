#version 330 core
// Screen-sized dots, stage 3: anti-aliased disc with a darker rim so it reads on any background.
in vec4 gColor;
in vec2 gOffset;
flat in float gRadius;
out vec4 fragColor;
void main() {
  float r = length(gOffset);
  float coverage = clamp(gRadius + 0.5 - r, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  float rim = smoothstep(gRadius - 2.0, gRadius - 1.0, r);
  vec3 color = mix(gColor.rgb, gColor.rgb * 0.45, rim);
  fragColor = vec4(color, gColor.a * coverage);
}
