#version 330 core
// SPDX-License-Identifier: MIT
in vec2 uv;
uniform sampler2D draft;
uniform float opacity;  // 0.5 over the release row so the sand under it stays visible
out vec4 fragColor;

void main() { fragColor = vec4(texture(draft, uv).rgb, opacity); }
