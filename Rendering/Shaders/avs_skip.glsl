// Empty-space skipping (Rendering/Core/OccupancyGrid.h): the occupancy of cells of
// u_cellSize^3 voxels, 0 where no sample inside can have sigma_t > 0. Leap(i) takes the ray from
// its sample i over the empty cells to the first sample of the ray's own grid beyond them, so
// the samples the ray takes are those of the ray that marched through, and the picture is the
// same. The effect learns of each leap through EffectLeap(from, to) where it defines
// AVS_EFFECT_LEAP (the samples [from, to) were empty: T did not change over them). Put in after
// the effect's declarations, for the composite blend only (the other blend modes read every
// sample's scalar).
#ifdef AVS_SKIP
uniform sampler3D u_occupancy;   // one texel per cell, nearest (texelFetch)
uniform vec3 u_occupancyCells;   // cells per axis
uniform float u_cellSize;        // voxels per cell and axis
int g_checkFrom = 0;             // the samples before it lie in a cell found occupied

// The first sample at or after i that may have material (i itself when its cell may), or
// `steps`; g_checkFrom is then the first sample past that sample's cell.
int Leap(int i)
{
  int first = i;
  g_checkFrom = i + 1;
  // Each turn tests one cell; a ray crosses at most this many cells (the loop's bound for the
  // compiler; the volume's diagonal in cells is shorter).
  for (int n = 0; n < 4096 && i < steps; ++n)
  {
    float t = t0 + (float(i) + offset) * dtWorld;
    vec3 index = io + t * id;
    vec3 cell = clamp(floor(index / u_cellSize), vec3(0.0), u_occupancyCells - 1.0);
    // Where the ray leaves the cell: through the face ahead on each axis (the first and last
    // cells reach the box's border, where the ray ends anyway: no face there).
    vec3 low = mix(cell * u_cellSize, vec3(-1e30), equal(cell, vec3(0.0)));
    vec3 high = mix((cell + 1.0) * u_cellSize, vec3(1e30), equal(cell, u_occupancyCells - 1.0));
    vec3 ahead = mix(index - low, high - index, greaterThanEqual(id, vec3(0.0)));
    vec3 exits = ahead / max(abs(id), vec3(1e-20));
    float leave = t + min(min(exits.x, exits.y), exits.z);
    // The first sample at or past the exit (at least the next one).
    float after = ceil((leave - t0) / dtWorld - offset);
    int next = max(i + 1, int(clamp(after, 0.0, float(steps))));
    if (texelFetch(u_occupancy, ivec3(cell), 0).r > 0.0)
    {
      g_checkFrom = next;
      break;
    }
    i = next;
  }
  i = min(i, steps);
#ifdef AVS_EFFECT_LEAP
  if (i > first)
  {
    EffectLeap(first, i);
  }
#endif
  return i;
}
#endif
