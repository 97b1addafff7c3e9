// avs-soak --time-series: a simulation played step by step for a long time, checked for a steady
// state. Three windows, each with one of the mappers (ambient scattering in the extended model
// with a directional and a point light, ambient occlusion, emission-absorption), show the same
// series: a procedural nebula moving one voxel along x per step, delivered as a reader delivers
// it (a new image each step) or as a source does (the same image's values rewritten and
// marked modified), in alternation; every tenth step changes a block of slices alone; and in
// each fifty steps, five steps repeat the step before them (new images with the same values: a
// static series, or a pause in the simulation).
//
// Checks: every step with new values uploads (the change of a block writes some voxels and
// less than half of them) and draws without an error; a repeated step uploads and rebuilds
// nothing and gives the frame of the step it repeats, bit for bit; at every checkpoint (each 25
// steps) each window's frame is what a new mapper draws from that step alone in a new window, bit
// for bit; from the first checkpoint on, no window holds more GL objects than it did there, each
// mapper's GPU memory is what it was after the first step, and the process's resident memory
// peaks at most 32 MiB above its peak over the first 100 steps (not compared under
// AddressSanitizer, whose quarantine keeps freed memory; LeakSanitizer checks for leaks at exit).
#ifndef SoakTimeSeries_h
#define SoakTimeSeries_h

/// Plays `steps` steps (at least 100); prints what it measured and returns whether every check
/// held. `addressSanitizer`: the resident memory is not compared.
bool RunTimeSeriesSoak(int steps, bool addressSanitizer);

#endif
