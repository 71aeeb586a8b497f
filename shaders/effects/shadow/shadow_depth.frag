#version 450 core
// The shadow pass writes depth only; no colour attachment exists. (The chapter's shadow.frag also
// discards below an alpha cutoff for cut-out textures; fxlab's scenes have none, so nothing is
// sampled here.)
void main() {}
