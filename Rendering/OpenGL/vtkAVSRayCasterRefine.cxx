// vtkAVSRayCaster's still frames of the path-traced refinement (vtkAVSRefinement): the GPU path
// tracer gets the ray caster's classification, clipping, lights, camera and depth.
#include "vtkAVSRayCaster.h"

#include "vtkAVSFrameUniforms.h"
#include "vtkAVSShaderAssembly.h"
#include "vtkAVSShaderOptions.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

bool vtkAVSRayCaster::Refine(vtkRenderer* renderer,
  const Frame& frame,
  vtkShaderProgram* program,
  const std::function<void()>& drawPass,
  int x,
  int y,
  int width,
  int height,
  std::string& error)
{
  // Reduced frames (the interactor's, or any image sample distance other than 1) show the
  // ambient-scattering picture and add nothing.
  if (!frame.Refinement.Still || frame.ImageSampleDistance != 1.0)
  {
    return false;
  }
  vtkOpenGLRenderWindow* window = this->Window;
  vtkAVSVolumeTextures& tx = this->Textures;
  vtkAVSRefinement& refinement = this->Refinement;
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  if (!refinement.HasAmbient())
  {
    refinement.CaptureAmbient(
      [&]
      {
        cache->ReadyShaderProgram(program);
        program->SetUniformi("u_displayInRay", 0); // the refined picture applies it
        drawPass();
      });
  }
  if (refinement.GetSamples() < frame.Refinement.MaximumSamples)
  {
    if (!refinement.UpdateMajorants(
          tx.MajorantValues, tx.ValueRanges.Cells(), tx.MajorantsVersion, error))
    {
      return false;
    }
    const vtkAVSClassification::Layout& layout = tx.Classification.GetLayout();
    const std::string defines =
      vtkAVSShaderAssembly::RayCastDefines(avs::RenderMode::AmbientScattering,
        frame.Parameters,
        frame.Lights,
        static_cast<int>(tx.TableSize[1]),
        layout) +
      vtkAVSShaderOptions::ClipDefines(frame.Clip);
    const bool added = refinement.AddSample(
      defines,
      [&](vtkShaderProgram* pt)
      {
        vtkAVSFrameUniforms::SetGeometry(pt, renderer, width, height, frame);
        vtkAVSFrameUniforms::SetLights(pt, frame.Lights);
        vtkAVSFrameUniforms::SetParameters(pt, frame);
        vtkAVSShaderOptions::SetClipUniforms(pt, frame.Clip);
        pt->SetUniformi("u_depth", this->Depth.GetTexture()->GetTextureUnit());
        vtkAVSVolumeTextures::SetVolumeFilter(tx.Scalars, layout.Nearest);
        pt->SetUniformi("u_scalars", tx.Scalars->GetTextureUnit());
        pt->SetUniformf("u_majorantCellSize", static_cast<float>(tx.ValueRanges.CellSize()));
        tx.Classification.Bind(static_cast<unsigned int>(pt->GetHandle()));
        tx.Surfaces.Bind(static_cast<unsigned int>(pt->GetHandle()), layout.Nearest);
      },
      error);
    if (!added)
    {
      return false;
    }
    // The ray caster's program is current again for what follows.
    cache->ReadyShaderProgram(program);
  }
  if (!refinement.Show(x, y, width, height, frame.Display))
  {
    error = "the refined picture's shader did not compile (see the log above)";
    return false;
  }
  return true;
}
