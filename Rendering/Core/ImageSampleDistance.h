// How the mappers choose the image sample distance of a frame from the time allotted to it
// (vtkAVSVolumeMapper's AutoAdjustSampleDistances): the number of rays is what a frame's cost
// scales with, so the distance d that fits the allotted time t is sqrt(P s / t) for P pixels at
// s seconds per ray. VTK-free, unit-tested (Testing/Unit/TestImageSampleDistance.cxx).
#ifndef avs_ImageSampleDistance_h
#define avs_ImageSampleDistance_h

namespace avs
{

/// Image sample distances are chosen in steps of this many pixels, so that a picture changes its
/// size only when the frame time calls for it.
constexpr double ImageSampleDistanceStep = 0.5;

struct FrameBudget
{
  double AllocatedSeconds = 0.0; ///< the time allotted to the frame (vtkProp)
  double SecondsPerRay = 0.0;    ///< measured on earlier frames; 0: not measured yet
  double Pixels = 0.0;           ///< the viewport's pixels (full resolution)
  double Previous = 1.0;         ///< the distance of the previous frame
  double Minimum = 1.0;          ///< the clamp (MinimumImageSampleDistance)
  double Maximum = 10.0;         ///< the clamp (MaximumImageSampleDistance)
};

/// The image sample distance (pixels per ray along each axis) for a frame: the one whose rays
/// fit the allotted time, taken at once when it is coarser than the previous frame's (over
/// budget) and averaged with it as a resolution factor (1 / d) when finer (against flicker),
/// rounded up to a multiple of ImageSampleDistanceStep and clamped to [Minimum, Maximum]. Without
/// a measurement or an allotted time, the previous distance, clamped.
double ChooseImageSampleDistance(const FrameBudget& budget);

/// The number of rays along an axis of `pixels` pixels at image sample distance `distance` (at
/// least 1).
int SampledSize(int pixels, double distance);

} // namespace avs

#endif
