#version 330 core
// Thick lines, stage 2: each segment becomes a screen-space quad uWidth pixels wide (core profile has
// no glLineWidth > 1). Segments are clipped against the near plane first so that end points behind
// the eye do not flip; ends are extended by half the width so polylines join without gaps.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
in vec4 vColor[];
uniform vec2 uViewport;  // pixels
uniform float uWidth;    // pixels
out vec4 gColor;
noperspective out float gAcross;  // pixels from the centre line

void main() {
  vec4 p0 = gl_in[0].gl_Position, p1 = gl_in[1].gl_Position;
  vec4 c0 = vColor[0], c1 = vColor[1];
  float d0 = p0.z + p0.w, d1 = p1.z + p1.w;  // signed distance to the near plane
  if (d0 < 0.0 && d1 < 0.0) return;
  if (d0 < 0.0) {
    float t = d0 / (d0 - d1);
    p0 = mix(p0, p1, t);
    c0 = mix(c0, c1, t);
  } else if (d1 < 0.0) {
    float t = d1 / (d1 - d0);
    p1 = mix(p1, p0, t);
    c1 = mix(c1, c0, t);
  }
  vec2 s0 = p0.xy / p0.w * 0.5 * uViewport;
  vec2 s1 = p1.xy / p1.w * 0.5 * uViewport;
  vec2 dir = s1 - s0;
  float len = length(dir);
  dir = len > 1e-4 ? dir / len : vec2(1.0, 0.0);
  vec2 normal = vec2(-dir.y, dir.x);
  float half_ = 0.5 * uWidth + 1.0;  // +1 px for the anti-aliased fringe
  vec2 toNdc = 2.0 / uViewport;
  vec2 along = dir * (0.5 * uWidth) * toNdc;
  vec2 across = normal * half_ * toNdc;
  gColor = c0; gAcross = half_;
  gl_Position = vec4(p0.xy + (across - along) * p0.w, p0.zw); EmitVertex();
  gColor = c0; gAcross = -half_;
  gl_Position = vec4(p0.xy + (-across - along) * p0.w, p0.zw); EmitVertex();
  gColor = c1; gAcross = half_;
  gl_Position = vec4(p1.xy + (across + along) * p1.w, p1.zw); EmitVertex();
  gColor = c1; gAcross = -half_;
  gl_Position = vec4(p1.xy + (-across + along) * p1.w, p1.zw); EmitVertex();
  EndPrimitive();
}
