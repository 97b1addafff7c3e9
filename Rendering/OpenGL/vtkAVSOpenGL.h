/**
 * OpenGL through VTK's loader (private): GLEW (vtk_glew.h, the module VTK::glew) up to VTK 9.3,
 * glad (vtk_glad.h, VTK::glad) from VTK 9.4 on. The module links whichever the VTK it is built
 * against has (Rendering/vtk.module, OPTIONAL_DEPENDS).
 */
#ifndef vtkAVSOpenGL_h
#define vtkAVSOpenGL_h

#include "vtkVersionMacros.h"

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
#include "vtk_glad.h" // IWYU pragma: export
#else
#include "vtk_glew.h" // IWYU pragma: export
#endif

#endif
