#version 330 core
// SPDX-License-Identifier: MIT
// Points are flat; sprites and billboards are round grains with a soft shade toward the rim
// (the thesis's shaded sprite texture, computed here instead of sampled).

flat in vec3 shadedColor;
in vec2 quadCorner;
uniform int mode;
out vec4 fragColor;

void main() {
    if (mode == 0) {
        fragColor = vec4(shadedColor, 1.0);
        return;
    }
    vec2 c = mode == 1 ? vec2(2.0 * gl_PointCoord.x - 1.0, 1.0 - 2.0 * gl_PointCoord.y) : quadCorner;
    float r2 = dot(c, c);
    if (r2 > 1.0) discard;
    float dome = sqrt(1.0 - r2);
    float shade = 0.72 + 0.28 * dome + 0.10 * dot(c, vec2(-0.5, 0.7));
    fragColor = vec4(shadedColor * shade, 1.0);
}
