// Which part of the volume is there: clipping planes and cropping in the data's continuous index
// frame, the GPU's copy of Rendering/Core/ClipRegion.cxx (which the CPU reference and the tests
// use). Put in at //AVS::Clip::Dec by the ray caster and the averaged-extinction pass.
//
// u_clipPlanes[p] = (n, w): kept where dot(n, index) + w >= 0. Cropping: two planes per index
// axis (u_cropLow, u_cropHigh) make 27 regions; region a + 3 b + 9 c is kept where that bit of
// u_cropFlags is set (VTK's numbering). u_keptLow/u_keptHigh bound the kept regions, so a ray is
// shortened to the planes' interval and to that box once (ClipRay), and only the regions are
// tested per sample (ClipInside).
//
// In the ray caster, AVS_CLIPPING (planes or cropping) and AVS_CROPPING are compile-time
// choices, so a volume that is not clipped pays nothing; the compute pass tests the uniforms.
uniform int u_clipPlaneCount;
uniform vec4 u_clipPlanes[8];
uniform int u_cropping;
uniform vec3 u_cropLow;
uniform vec3 u_cropHigh;
uniform int u_cropFlags;
uniform vec3 u_keptLow;
uniform vec3 u_keptHigh;

// Shortens [t0, t1] of the ray index(t) = o + t d; false when nothing is left.
bool ClipRay(vec3 o, vec3 d, inout float t0, inout float t1)
{
  for (int p = 0; p < u_clipPlaneCount; ++p)
  {
    float a = dot(u_clipPlanes[p].xyz, o) + u_clipPlanes[p].w;
    float b = dot(u_clipPlanes[p].xyz, d);
    if (b > 0.0)
      t0 = max(t0, -a / b);
    else if (b < 0.0)
      t1 = min(t1, -a / b);
    else if (a < 0.0)
      return false;
  }
  if (u_cropping == 1)
  {
    vec3 inverse = 1.0 / d; // +-inf on axes the ray runs parallel to
    vec3 u = (u_keptLow - o) * inverse;
    vec3 v = (u_keptHigh - o) * inverse;
    vec3 near = min(u, v), far = max(u, v);
    for (int axis = 0; axis < 3; ++axis)
    {
      if (d[axis] == 0.0)
      {
        if (o[axis] < u_keptLow[axis] || o[axis] > u_keptHigh[axis])
          return false;
      }
      else
      {
        t0 = max(t0, near[axis]);
        t1 = min(t1, far[axis]);
      }
    }
  }
  return t1 > t0;
}

// 1 where the continuous index lies in a kept cropping region (and inside every plane when
// `planes` is true), else 0.
float ClipInside(vec3 index, bool planes)
{
  if (planes)
  {
    for (int p = 0; p < u_clipPlaneCount; ++p)
    {
      if (dot(u_clipPlanes[p].xyz, index) + u_clipPlanes[p].w < 0.0)
        return 0.0;
    }
  }
  if (u_cropping == 1)
  {
    ivec3 cell = ivec3(step(u_cropLow, index) + step(u_cropHigh, index));
    int region = cell.x + 3 * cell.y + 9 * cell.z;
    return float((u_cropFlags >> region) & 1);
  }
  return 1.0;
}

// At the classification call sites of the ray caster: sigma_t of a sample at `index` is 0 in a
// cropped-away region (the planes have shortened the ray already).
#ifdef AVS_CROPPING
#define AVS_CROP(classified, index) classified.a *= ClipInside(index, false)
#define AVS_KEPT(index) (ClipInside(index, false) > 0.5)
#else
#define AVS_CROP(classified, index)
#define AVS_KEPT(index) true
#endif
