// Screen-sized dots: one instance per dot, a 4-vertex triangle strip (gl_VertexID picks the corner)
// of the dot's diameter plus a 1 px fringe around the point.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColor;
layout(location = 2) in float aSize;  // diameter, pixels
uniform mat4 uViewProj;
uniform vec2 uViewport;
uniform float uSizeScale;  // lecture mode enlarges dots
out vec4 vColor;
out vec2 vOffset;  // pixels from the centre
flat out float vRadius;
void main() {
  vec4 p = uViewProj * vec4(aPosition, 1.0);
  vColor = aColor;
  vRadius = 0.5 * aSize * uSizeScale;
  vec2 corner = vec2((gl_VertexID & 1) == 0 ? -1.0 : 1.0, gl_VertexID < 2 ? -1.0 : 1.0);
  vOffset = corner * (vRadius + 1.0);
  if (p.w <= 0.0) {  // behind the eye: a degenerate quad outside the clip box
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  vec2 toClip = 2.0 / uViewport * p.w;
  gl_Position = vec4(p.xy + vOffset * toClip, p.zw);
}
