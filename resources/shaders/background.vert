// Full-screen triangle (no vertex buffer): gl_VertexID 0..2.
out float vHeight;  // 0 at the bottom of the screen, 1 at the top
void main() {
  vec2 p = vec2((gl_VertexID == 1) ? 3.0 : -1.0, (gl_VertexID == 2) ? 3.0 : -1.0);
  vHeight = p.y * 0.5 + 0.5;
  gl_Position = vec4(p, 1.0, 1.0);
}
