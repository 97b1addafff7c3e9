/**
 * @class   vtkAVSFrameUniforms
 * @brief   the ray-casting program's uniforms that follow from a frame alone (private)
 *
 * What vtkAVSRayCaster::Render sets from its Frame besides the textures: the camera and the
 * volume's placement (avs_raycast_fs.glsl), the lights (avs_lights.glsl) and the resolved
 * avs::ScatteringParameters of the effect (the walk from a mapper's parameters to the shader:
 * the mapper's FillParameters, ScatteringParameters::Resolve, Frame::Parameters, SetParameters).
 */
#ifndef vtkAVSFrameUniforms_h
#define vtkAVSFrameUniforms_h

#include "vtkAVSRayCaster.h"

class vtkRenderer;
class vtkShaderProgram;

class vtkAVSFrameUniforms
{
public:
  /// NDC -> world from the renderer's camera at the viewport's aspect, world -> index, the
  /// grid's dimensions, spacing and border.
  static void SetGeometry(vtkShaderProgram* program,
    vtkRenderer* renderer,
    int width,
    int height,
    const vtkAVSRayCaster::Frame& frame);
  /// The first vtkAVSRayCaster::MaximumNumberOfLights lights (world space).
  static void SetLights(vtkShaderProgram* program, const std::vector<avs::Light>& lights);
  /// The effect's parameters: sampling and termination, the medium (albedo, anisotropy,
  /// emission), AO's weights or ambient scattering's radius, and the jitter.
  static void SetParameters(vtkShaderProgram* program, const vtkAVSRayCaster::Frame& frame);
  /// The display transform's uniforms (avs_display.glsl): exposure, tone curve, shoulder start.
  static void SetDisplay(vtkShaderProgram* program, const avs::DisplayTransform& display);
  /// A split volume's brick (vtkAVSBricks): its owned box, texture origin and size, and the
  /// gradient's voxel step in its texture.
  static void SetBrick(vtkShaderProgram* program, const vtkAVSBricks::Brick& brick);
  /// Where the bricks are seen from, in the data's continuous index frame: the camera, or for
  /// a parallel projection a point outside the grid on the side each axis's rays come from.
  static std::array<double, 3> EyeInIndexFrame(vtkRenderer* renderer,
    const vtkAVSRayCaster::Frame& frame);
};

#endif
