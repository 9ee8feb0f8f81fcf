#version 330 core
// Writes which patch this pixel sees. A patch seen from behind still hides what lies beyond it, but
// a one-sided diffuse surface sends nothing toward its back, so the item says so (the top bit) and
// the gather leaves it out of form factors and irradiance. The side is decided from the patch's
// normal, not from the triangle's winding, so meshes of either orientation work.
in vec3 worldPosition;
flat in vec3 patchNormal;
flat in uint patchItem;

uniform vec3 eye;

layout(location = 0) out uint itemOut;

void main() {
    bool front = dot(patchNormal, eye - worldPosition) > 0.0;
    itemOut = front ? patchItem : (patchItem | 0x80000000u);
}
