// The particle programs' uniform locations and buffer bindings, written once for the shaders and the
// C++ (effects/particles/particles_bindings.hpp).
// The storage buffers (std430): the pool, the emitter table, the live list, the stats and the
// indirect draw's command.
const int kParticlePoolBinding = 0;
const int kParticleEmittersBinding = 1;
const int kParticleLiveBinding = 2;
const int kParticleStatsBinding = 3;
const int kParticleCommandBinding = 4;
// particle.vert and particle.frag (the sprites; their hdrMax is scene_bindings.glsl's kHdrMaxLocation)
const int kParticleViewLocation = 0;               // mat4
const int kParticleProjectionLocation = 1;         // mat4
const int kParticleOneOriginAgeLocation = 3;       // vec4: the particle of a one-per-draw draw
const int kParticleOneVelocityLifeLocation = 4;    // vec4
const int kParticleOneExtraLocation = 5;           // vec4
const int kParticleSoftDistanceLocation = 12;      // float
const int kParticleNearFarLocation = 13;           // vec2
const int kParticleDepthTexelsPerPixelLocation = 14;  // vec2
const int kParticleSpriteBinding = 0;  // sampler2D
const int kParticleSceneDepthBinding = 1;  // sampler2D
// simulate.comp
const int kSimulateFirstSlotLocation = 0;    // uint
const int kSimulateSlotsLocation = 1;        // uint
const int kSimulateHeadLocation = 2;         // uint
const int kSimulateSpawnCountLocation = 3;   // uint
const int kSimulateFirstNumberLocation = 4;  // uint
const int kSimulateNewestAgeLocation = 5;    // float
const int kSimulatePeriodLocation = 6;       // float
const int kSimulateDtLocation = 7;           // float
const int kSimulateChapterLifetimeLocation = 8;  // int
const int kSimulateOriginLocation = 9;       // vec3
const int kSimulateRiseSpeedLocation = 10;   // float
const int kSimulateSpreadLocation = 11;      // float
const int kSimulateSeedLocation = 12;        // uint
const int kSimulateLifetimeLocation = 13;    // float
const int kSimulateEmitterIndexLocation = 14;  // uint
// compact.comp
const int kCompactTotalSlotsLocation = 1;  // uint
// pool_view.comp
const int kPoolViewSlotsLocation = 0;         // uint
const int kPoolViewEmitterScaleLocation = 1;  // float
const int kPoolViewImageBinding = 0;          // rgba32f image
