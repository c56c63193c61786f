// OpenGL 4.5 core, declared by the system's headers (Debian: libgl-dev) and linked through GLVND's
// libOpenGL, which dispatches each call to the driver of the current context.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
