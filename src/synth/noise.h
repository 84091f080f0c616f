#pragma once
// Hash-based value noise for procedural materials: a pure function of the world position (and a
// key), so a surface point has the same colour in every view and every thread.
#include <cstdint>

namespace cls::synth {

// Smooth value noise in [0, 1] with unit lattice spacing.
float value_noise(float x, float y, float z, uint64_t key);

// Fractal sum of `octaves` value-noise layers (frequency x2, amplitude x0.5 each), in [0, 1].
float fbm(float x, float y, float z, int octaves, uint64_t key);

// A value in [0, 1) that is constant on the integer cell (i, j, k): per-tile / per-brick variation.
float cell_random(int64_t i, int64_t j, int64_t k, uint64_t key);

}  // namespace cls::synth
