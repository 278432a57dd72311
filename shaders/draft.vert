#version 330 core
// SPDX-License-Identifier: MIT
// SPEC P5: the draft quad over the canvas rectangle; u runs along +x, v along +z.
uniform mat4 viewProjection;
uniform vec3 origin;  // world position of the canvas corner at column (0, 0), world units
uniform vec2 extent;  // width along x and depth along z, world units

out vec2 uv;

const vec2 corners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));

void main() {
    uv = corners[gl_VertexID];
    gl_Position = viewProjection * vec4(origin + vec3(uv.x * extent.x, 0.0, uv.y * extent.y), 1.0);
}
