#pragma once
// The one header through which fxlab sees OpenGL: glad's GL 4.5 core loader, generated at
// configure time into the build tree.
#include <glad/gl.h>
