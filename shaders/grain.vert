#version 330 core
// SPDX-License-Identifier: MIT
// One sand grain per instance; gl_VertexID picks the sub-grain (thesis §3.8 "Scribble") and,
// for quads, the corner. The CPU supplies per grain its position, its estimated normal and
// whether it is inner (inner grains are left out of the instances); the sub-grain offsets,
// sizes, colours and lighting are worked out here.

layout(location = 0) in vec3 grainPosition;   // R8 display position, world units
layout(location = 1) in vec4 grainNormal;     // packed 10:10:10:2, unit normal
layout(location = 2) in uint grainIdentity;   // picks the pattern
layout(location = 3) in uint grainColor;      // RGBA8, 0 = the pattern's sand colour
layout(location = 4) in uint grainOcclusion;  // occlusion level, (occupied neighbours + 2) / 4

#include "grain_shading.glsl"

uniform mat4 viewProjection;
uniform int mode;                // 0 points, 1 sprites, 2 billboards, 3 pseudo-billboards
uniform float cellSize;          // world units per cell
uniform float pointSize;         // points and sprites, pixels
uniform float quadHalfSize;      // billboards, world units
uniform vec3 cameraPosition;     // world units
uniform vec3 cameraUp;           // unit, world space
uniform vec3 pseudoRight;        // pseudo-billboards: the camera's rotation applied once per frame
uniform vec3 pseudoUp;
uniform sampler2D patternOffsets; // x: sub-grain (0..31), y: pattern; xyz in [-1, 1]
uniform sampler2D patternColors;  // same layout, RGBA8
uniform int patternCount;

flat out vec3 shadedColor; // one colour a sub-grain: its first corner's (glProvokingVertex)
out vec2 quadCorner;

// A quad's 4 corners; its two triangles index them (0 1 2, 0 2 3), so a GPU shades each corner once.
const vec2 corners[4] = vec2[4](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
    bool quads = mode >= 2;
    int subGrain = quads ? gl_VertexID / 4 : gl_VertexID;
    ivec2 texel = ivec2(subGrain, int(grainIdentity % uint(patternCount)));
    vec3 centre = grainPosition + texelFetch(patternOffsets, texel, 0).xyz * (0.5 * cellSize);

    vec3 base = texelFetch(patternColors, texel, 0).rgb;
    if (grainColor != 0u) {
        vec3 own = vec3(float(grainColor & 255u), float((grainColor >> 8) & 255u), float((grainColor >> 16) & 255u)) / 255.0;
        base = own * (base / vec3(0.90, 0.90, 0.67)); // keep the pattern's small variation
    }
    // A quad's colour is its first corner's (flat, first-vertex convention): the others skip the light.
    bool shades = !quads || gl_VertexID % 4 == 0;
    shadedColor = shades ? shadeGrain(base, grainNormal.xyz, int(grainOcclusion), centre) : vec3(0.0);

    vec3 world = centre;
    quadCorner = vec2(0.0);
    if (quads) {
        quadCorner = corners[gl_VertexID % 4];
        vec3 right, up;
        if (mode == 2) {
            // Thesis §3.8 billboard: l = look at this grain, r = C_up x l, u = l x r.
            vec3 look = normalize(centre - cameraPosition);
            right = normalize(cross(cameraUp, look));
            up = cross(look, right);
            right = -right; // keep the texture's left on the screen's left
        } else {
            right = pseudoRight;
            up = pseudoUp;
        }
        world += (quadCorner.x * right + quadCorner.y * up) * quadHalfSize;
    } else {
        gl_PointSize = pointSize;
    }
    gl_Position = viewProjection * vec4(world, 1.0);
}
