// The cloud passes' uniform locations, written once for the shaders and the C++
// (effects/clouds/clouds_bindings.hpp). The march and the cloud shadow map share the camera and slab
// uniforms at the same places, so setCloudCameraUniforms serves both.
// clouds.frag and cloud_shadow.frag
const int kCloudsInverseProjectionLocation = 0;    // mat4
const int kCloudsViewToWorldRotationLocation = 1;  // mat3
const int kCloudsCameraPositionLocation = 2;       // vec3
const int kCloudsOffsetsLocation = 3;              // vec4: both layers' wrapped offsets
const int kCloudsRangeCountStepLocation = 4;       // vec4: bottom, top, samples, step
const int kCloudsThresholdPairLocation = 5;        // vec2
const int kCloudsScalesLocation = 7;               // vec2
const int kCloudsTargetSizeLocation = 14;          // vec2
// clouds.frag only
const int kCloudsColourLocation = 6;         // vec3
const int kCloudsShadowOffsetLocation = 10;  // float
const int kCloudsFrameIndexLocation = 12;    // int
const int kCloudsPlaneHeightLocation = 13;   // float
const int kCloudsDepthStrideLocation = 16;   // int
// cloud_shadow.frag only
const int kCloudShadowToLightLocation = 8;          // vec3
const int kCloudShadowSamplesLocation = 9;          // int
const int kCloudShadowSigmaPerDensityLocation = 10;  // float
// cloud_shadow_apply.frag
const int kCloudShadowSunShareLocation = 0;  // float
// cloud_accumulate.frag
const int kAccumulateInverseProjectionLocation = 0;    // mat4
const int kAccumulateViewToWorldRotationLocation = 1;  // mat3
const int kAccumulatePreviousFromCameraLocation = 2;   // mat4
const int kAccumulateSlabMiddleAndEyeYLocation = 3;    // vec2
const int kAccumulateCurrentWeightLocation = 4;        // float
const int kAccumulateTargetSizeLocation = 5;           // vec2
const int kAccumulateDepthStrideLocation = 6;          // int
