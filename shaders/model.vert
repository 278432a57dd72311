#version 330 core
// SPDX-License-Identifier: MIT
// A model drawn as modelled (SPEC S10): its parts' own triangles with smooth normals.
layout(location = 0) in vec3 position; // world units
layout(location = 1) in vec3 normal;   // unit; its sign follows the triangle's winding
layout(location = 2) in vec3 color;    // the part's material colour

uniform mat4 viewProjection;
uniform vec3 offset; // world units added to every position (a moving body's place; 0 for a model)

out vec3 worldPosition;
out vec3 worldNormal;
out vec3 partColor;

void main() {
    worldPosition = position + offset;
    worldNormal = normal;
    partColor = color;
    gl_Position = viewProjection * vec4(worldPosition, 1.0);
}
