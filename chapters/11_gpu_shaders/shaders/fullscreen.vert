// One triangle that covers the whole viewport: vertices (−1, −1), (3, −1), (−1, 3) from gl_VertexID alone
// (no vertex buffer). Its clipped part is the screen: every pixel gets exactly one fragment.

void main() {
    const vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
