// One particle and one emitter as the buffers hold them (common/effects/particles/particle_layout.hpp),
// the seeded integer hash (particle_hash.hpp) and what a particle looks like at its age. Every path
// (one draw per particle, instanced, GPU-simulated) computes these the same way.
struct Particle {
    vec4 originAge;     // xyz: where it was born; w: age (s)
    vec4 velocityLife;  // xyz: m/s; w: lifetime (s)
    vec4 extra;         // x: angle at birth; y: emitter index; z: 1 alive
};

struct Emitter {
    vec4 startColor;
    vec4 endColor;
    vec4 size;    // start, end, lifetime, coverage (0 adds light, 1 covers)
    vec4 motion;  // spin (rad/s), 1 = the chapter's unclamped age, 1 = textured
    uvec4 ring;   // first slot, slots, oldest slot
};

uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

float particleRandom(uint seed, uint number, uint channel) {
    uint h = pcgHash(seed ^ pcgHash(number ^ pcgHash(channel)));
    return float(h >> 8u) * (1.0 / 16777216.0);
}

// Where the particle is, how wide, its colour and its angle about the view axis.
struct ParticleLook {
    vec3 position;
    float size;
    vec4 color;
    float angle;
};

ParticleLook particleLook(Particle p, Emitter e) {
    ParticleLook look;
    float age = p.originAge.w;
    float life = max(p.velocityLife.w, 1e-6);
    float t = age / life;
    // The chapter keeps fading past the end of the life (alpha below 0); the fix clamps the age.
    if (e.motion.y == 0.0) t = clamp(t, 0.0, 1.0);
    look.position = p.originAge.xyz + p.velocityLife.xyz * age;
    look.size = max(mix(e.size.x, e.size.y, t), 0.0);
    look.color = mix(e.startColor, e.endColor, t);
    // The age is at most the lifetime (60 s), so the angle stays small enough for sin and cos.
    look.angle = p.extra.x + e.motion.x * age;
    return look;
}
