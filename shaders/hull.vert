#version 330 core
// SPDX-License-Identifier: MIT
// The glass vessel (SPEC V6) and the canvas outline.
layout(location = 0) in vec3 position;  // world units
layout(location = 1) in vec3 normal;    // unit, into the wall; zero for outline lines

uniform mat4 viewProjection;
uniform vec3 cameraPosition;

out float facing;   // |cos| between the view ray and the wall normal: 1 = seen head-on
out vec3 worldPosition;
out vec3 worldNormal; // zero for lines

void main() {
    vec3 view = normalize(cameraPosition - position);
    facing = dot(normal, normal) > 0.5 ? abs(dot(normalize(normal), view)) : 1.0;
    worldPosition = position;
    worldNormal = normal;
    gl_Position = viewProjection * vec4(position, 1.0);
}
