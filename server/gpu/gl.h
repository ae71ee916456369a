#pragma once
// The one include for GL declarations: core profile only, entry points
// exported by glvnd's libOpenGL (GL_GLEXT_PROTOTYPES is set by toond_gpu).
#include <GL/glcorearb.h>
