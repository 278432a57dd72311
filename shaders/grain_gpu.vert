#version 330 core
// SPDX-License-Identifier: MIT
// SPEC V8: one sand grain per instance, as the GPU keeps it between frames (grain_gpu_store.hpp):
// its cell, grid and last move, uploaded only when it moves. The display position is worked out
// here exactly as sandcore::grainDisplayPosition does (R8): (world cell + 1/2 + jitter + the
// share of the move still ahead) * cellSize, summed in the same order, never accumulated.
// gl_VertexID picks the sub-grain (thesis §3.8 "Scribble") and, for quads, the corner; when
// inner grains are hidden, the instances are the visible list's ids, or, when the store holds the
// cells' occupancy bits (flagsFromBits), every grain, and the inner ones are dropped here: their
// flag and their gradient normal are worked out from the bits exactly as sandcore::isInnerGrain
// and sandcore::occupancyGradientSums do on the CPU.

layout(location = 0) in uint visibleGrain;  // inner grains hidden: the id of a visible grain

#include "grain_shading.glsl"

// Per grain id (grain_gpu_store.hpp):
uniform usamplerBuffer grainPlaces;   // cell, level (0 lower, 1 upper), cameFrom, step of the last move
uniform usamplerBuffer grainLooks;    // identity (picks the pattern), RGBA8 colour (0 = the pattern's)
uniform samplerBuffer grainJitters;   // sandcore::jitterOffset, cells
uniform usamplerBuffer grainSurfaceKeys; // sandcore's key: gradient sums + 6859 x occlusion level
// Per cell, one bit (cell n: bit n % 32 of word n / 32): holds a grain; is not EMPTY (hides).
uniform usamplerBuffer cellBits;
uniform ivec4 cellBitsOffsets;   // first word of: lower grains, upper grains, lower hides, upper hides
uniform usamplerBuffer gradientNormalTable; // packed normal of each key (gx+9) + 19 (gy+9) + 361 (gz+9) + 6859 level
uniform bool flagsFromBits;      // inner flags and gradient normals from the bits

uniform ivec3 lowerSize;         // cells per axis of each grid
uniform ivec3 upperSize;
uniform ivec3 upperOrigin;       // world cell of the upper grid's (0, 0, 0)
uniform uint currentStep;        // low 32 bits of the steps done
uniform float stepRemaining;     // 1 - step fraction: share of a move still ahead (0: at rest)
uniform bool showInner;          // every grain is an instance (id = gl_InstanceID); else the visible list
uniform int keySource;           // the grain's surface key: 0 none, 1 per grain (grainSurfaceKeys), 2 from the bits
uniform bool normalFromKey;      // lit by the gradient normal of the key; else by its column's normal
uniform usampler2D columnNormals; // per column, packed 10:10:10:2; row z + level * sizeZ

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

out vec3 displayPosition; // the grain's R8 display point (read back by transform feedback in tests)
flat out vec3 shadedColor; // one colour a sub-grain: its first corner's (glProvokingVertex)
out vec2 quadCorner;

vec3 unpackNormal(uint word) {
    ivec3 bits = ivec3(int(word & 1023u), int((word >> 10) & 1023u), int((word >> 20) & 1023u));
    bits -= ivec3(greaterThanEqual(bits, ivec3(512))) * 1024;
    return max(vec3(bits) / 511.0, vec3(-1.0));
}

// The bit of cell n in the set starting at word `offset`.
bool cellBit(int offset, uint n) { return ((texelFetch(cellBits, offset + int(n >> 5u)).r >> (n & 31u)) & 1u) != 0u; }

uint cellIndex(ivec3 size, ivec3 p) { return uint(p.x + size.x * (p.z + size.z * p.y)); }

// sandcore's hidesAt: outside its grid a neighbour hides; inside, a grain or INVALID does.
bool hidesAt(bool upperGrid, ivec3 p) {
    ivec3 size = upperGrid ? upperSize : lowerSize;
    if (any(lessThan(p, ivec3(0))) || any(greaterThanEqual(p, size))) return true;
    return cellBit(upperGrid ? cellBitsOffsets.w : cellBitsOffsets.z, cellIndex(size, p));
}

// sandcore::isInnerGrain: 6 face neighbours hide; across the seam the lower grid's top row looks
// at the upper grid's layer 1 above, the upper grid's layer 0 at the lower grid's row sizeY-2.
bool innerGrain(bool upperGrid, ivec3 c) {
    if (!(hidesAt(upperGrid, c - ivec3(1, 0, 0)) && hidesAt(upperGrid, c + ivec3(1, 0, 0)) &&
          hidesAt(upperGrid, c - ivec3(0, 0, 1)) && hidesAt(upperGrid, c + ivec3(0, 0, 1))))
        return false;
    int lowerTop = lowerSize.y - 1;
    bool above = (!upperGrid && c.y == lowerTop) ? hidesAt(true, ivec3(c.x, 1, c.z)) : hidesAt(upperGrid, c + ivec3(0, 1, 0));
    bool below = (upperGrid && c.y == 0) ? hidesAt(false, ivec3(c.x, lowerTop - 1, c.z)) : hidesAt(upperGrid, c - ivec3(0, 1, 0));
    return above && below;
}

// sandcore::occupancyGradientSums: the offsets of the grains among the 26 neighbours within the
// grain's own grid (outside it nothing), and, from the same reads, sandcore::occupiedNeighbours
// as the occlusion level: the key SurfaceUpkeep keeps per grain.
int surfaceKey(bool upperGrid, ivec3 c) {
    ivec3 size = upperGrid ? upperSize : lowerSize;
    int offset = upperGrid ? cellBitsOffsets.y : cellBitsOffsets.x;
    ivec3 g = ivec3(0);
    int occupied = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
            for (int dx = -1; dx <= 1; ++dx) {
                ivec3 p = c + ivec3(dx, dy, dz);
                if (any(lessThan(p, ivec3(0))) || any(greaterThanEqual(p, size))) continue;
                if (cellBit(offset, cellIndex(size, p))) {
                    g += ivec3(dx, dy, dz);
                    occupied += 1;
                }
            }
    occupied -= 1; // the grain's own cell
    return (g.x + 9) + 19 * (g.y + 9) + 361 * (g.z + 9) + 6859 * ((occupied + 2) / 4);
}

const uint kNoMove = 0x80008080u; // sandcore::packMove(0, 0, 0)

// A quad's 4 corners; its two triangles index them (0 1 2, 0 2 3), so a GPU shades each corner once.
const vec2 corners[4] = vec2[4](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
    int id = (showInner || flagsFromBits) ? gl_InstanceID : int(visibleGrain);
    uvec4 grainPlace = texelFetch(grainPlaces, id);
    bool upper = (grainPlace.y & 1u) != 0u;
    ivec3 size = upper ? upperSize : lowerSize;
    uint cell = grainPlace.x;
    uint rest = cell / uint(size.x);
    ivec3 local = ivec3(int(cell % uint(size.x)), int(rest / uint(size.z)), int(rest % uint(size.z)));
    if (flagsFromBits && !showInner && innerGrain(upper, local)) {
        // Hidden: outside the clip volume, so nothing of it is drawn (decided before anything
        // else is fetched: most grains of a full bulb are inner).
        displayPosition = vec3(0.0);
        shadedColor = vec3(0.0);
        quadCorner = vec2(0.0);
        gl_PointSize = 1.0;
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    uvec2 look = texelFetch(grainLooks, id).xy;
    uint grainIdentity = look.x;
    uint grainColor = look.y;
    vec3 grainJitter = texelFetch(grainJitters, id).xyz;
    ivec3 worldCell = local + (upper ? upperOrigin : ivec3(0));
    vec3 ahead = vec3(0.0);
    if (grainPlace.w == currentStep && stepRemaining > 0.0 && grainPlace.z != kNoMove) {
        uint from = grainPlace.z;
        vec3 offset = vec3(float(int(from & 255u) - 128), float(int(from >> 16) - 32768), float(int((from >> 8) & 255u) - 128));
        ahead = stepRemaining * offset;
    }
    vec3 grainPosition = (vec3(worldCell) + 0.5 + grainJitter + ahead) * cellSize;
    displayPosition = grainPosition;

    bool quads = mode >= 2;
    int subGrain = quads ? gl_VertexID / 4 : gl_VertexID;
    // A quad's colour is its first corner's (flat, first-vertex convention): the other three
    // skip the neighbour reads and the light.
    bool shades = !quads || gl_VertexID % 4 == 0;
    ivec2 texel = ivec2(subGrain, int(grainIdentity % uint(patternCount)));
    vec3 centre = grainPosition + texelFetch(patternOffsets, texel, 0).xyz * (0.5 * cellSize);

    vec3 base = texelFetch(patternColors, texel, 0).rgb;
    if (grainColor != 0u) {
        vec3 own = vec3(float(grainColor & 255u), float((grainColor >> 8) & 255u), float((grainColor >> 16) & 255u)) / 255.0;
        base = own * (base / vec3(0.90, 0.90, 0.67)); // keep the pattern's small variation
    }
    shadedColor = vec3(0.0);
    if (shades) {
        int key = 0; // unlit and without occlusion: not read
        if (keySource == 2) key = surfaceKey(upper, local);
        else if (keySource == 1) key = int(texelFetch(grainSurfaceKeys, id).r);
        uint packedNormal = 0u;
        if (lighting) {
            if (normalFromKey) packedNormal = texelFetch(gradientNormalTable, key).r;
            else packedNormal = texelFetch(columnNormals, ivec2(local.x, local.z + (upper ? size.z : 0)), 0).r;
        }
        shadedColor = shadeGrain(base, unpackNormal(packedNormal), key / 6859, centre);
    }

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
