#version 330 core
// Screen-sized dots, stage 2: a quad of the dot's diameter (plus 1 px fringe) around the point.
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
in vec4 vColor[];
in float vSize[];
uniform vec2 uViewport;
uniform float uSizeScale;  // lecture mode enlarges dots
out vec4 gColor;
out vec2 gOffset;  // pixels from the centre
flat out float gRadius;
void main() {
  vec4 p = gl_in[0].gl_Position;
  if (p.w <= 0.0) return;
  float radius = 0.5 * vSize[0] * uSizeScale;
  float half_ = radius + 1.0;
  vec2 toClip = 2.0 / uViewport * p.w;
  const vec2 corners[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(-1, 1), vec2(1, 1));
  for (int i = 0; i < 4; ++i) {
    gColor = vColor[0];
    gRadius = radius;
    gOffset = corners[i] * half_;
    gl_Position = vec4(p.xy + gOffset * toClip, p.zw);
    EmitVertex();
  }
  EndPrimitive();
}
