#version 330 core
// SPEC V8: the grains drawn from what the GPU keeps (grain_gpu_store.hpp) and what the per-grain
// pass worked out this frame (grain_gpu_prepass.vert: display position, normal, inner flag, one
// entry per instance). This shader runs once per sub-grain and quad corner, so it only reads that
// entry: gl_VertexID picks the sub-grain (thesis §3.8 "Scribble") and, for quads, the corner.

layout(location = 0) in uint visibleGrain;  // inner grains hidden: the id of a visible grain

uniform usamplerBuffer grainLooks;    // per grain id: identity (picks the pattern), RGBA8 colour (0 = the pattern's)
uniform samplerBuffer grainCentres;   // per instance, from the per-grain pass: display position (xyz)
uniform usamplerBuffer grainShades;   // per instance: packed normal, bit 31 = inner (dropped)
uniform bool showInner;          // every grain is an instance (id = gl_InstanceID); else the visible list
uniform bool flagsFromBits;      // every grain is an instance, the inner ones marked by the pass

uniform mat4 viewProjection;
uniform int mode;                // 0 points, 1 sprites, 2 billboards, 3 pseudo-billboards
uniform float cellSize;          // world units per cell
uniform float pointSize;         // points and sprites, pixels
uniform float quadHalfSize;      // billboards, world units
uniform vec3 cameraPosition;     // world units
uniform vec3 cameraUp;           // unit, world space
uniform vec3 pseudoRight;        // pseudo-billboards: the camera's rotation applied once per frame
uniform vec3 pseudoUp;
uniform bool lighting;
uniform vec3 lightPosition;      // a white point light slightly below the camera (§3.8)
uniform sampler2D patternOffsets; // x: sub-grain (0..31), y: pattern; xyz in [-1, 1]
uniform sampler2D patternColors;  // same layout, RGBA8
uniform int patternCount;

out vec3 shadedColor;
out vec2 quadCorner;

vec3 unpackNormal(uint word) {
    ivec3 bits = ivec3(int(word & 1023u), int((word >> 10) & 1023u), int((word >> 20) & 1023u));
    bits -= ivec3(greaterThanEqual(bits, ivec3(512))) * 1024;
    return max(vec3(bits) / 511.0, vec3(-1.0));
}

const uint kInner = 0x80000000u;

// A quad's 4 corners; its two triangles index them (0 1 2, 0 2 3), so a GPU shades each corner once.
const vec2 corners[4] = vec2[4](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
    uint shade = texelFetch(grainShades, gl_InstanceID).r;
    if ((shade & kInner) != 0u) {
        // Hidden: outside the clip volume, so nothing of it is drawn.
        shadedColor = vec3(0.0);
        quadCorner = vec2(0.0);
        gl_PointSize = 1.0;
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    int id = (showInner || flagsFromBits) ? gl_InstanceID : int(visibleGrain);
    vec3 grainPosition = texelFetch(grainCentres, gl_InstanceID).xyz;
    uvec2 look = texelFetch(grainLooks, id).xy;
    uint grainIdentity = look.x;
    uint grainColor = look.y;

    bool quads = mode >= 2;
    int subGrain = quads ? gl_VertexID / 4 : gl_VertexID;
    ivec2 texel = ivec2(subGrain, int(grainIdentity % uint(patternCount)));
    vec3 centre = grainPosition + texelFetch(patternOffsets, texel, 0).xyz * (0.5 * cellSize);

    vec3 base = texelFetch(patternColors, texel, 0).rgb;
    if (grainColor != 0u) {
        vec3 own = vec3(float(grainColor & 255u), float((grainColor >> 8) & 255u), float((grainColor >> 16) & 255u)) / 255.0;
        base = own * (base / vec3(0.90, 0.90, 0.67)); // keep the pattern's small variation
    }
    if (lighting) {
        vec3 n = normalize(unpackNormal(shade));
        vec3 toLight = normalize(lightPosition - centre);
        float lambert = max(dot(n, toLight), 0.0);
        base *= 0.45 + 0.65 * lambert; // ambient keeps the side away from the light readable
    }
    shadedColor = base;

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
