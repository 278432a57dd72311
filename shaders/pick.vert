#version 330 core
// SPDX-License-Identifier: MIT
// SPEC P1: one quad per canvas column (instance = column index), made from gl_VertexID, so
// picking needs no vertex buffer. The id goes to the fragment shader unchanged.
uniform mat4 viewProjection;
uniform int columnsX;
uniform vec3 origin;     // world position of column 0's corner, world units
uniform float cellSize;  // world units per column

flat out uint columnId;

const vec2 corners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));

void main() {
    int column = gl_InstanceID;
    vec2 cell = vec2(column % columnsX, column / columnsX) + corners[gl_VertexID];
    columnId = uint(column) + 1u; // 0 stays "nothing"
    gl_Position = viewProjection * vec4(origin + vec3(cell.x, 0.0, cell.y) * cellSize, 1.0);
}
