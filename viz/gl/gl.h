// Everything of the GL runtime in one include.
#pragma once

#include "gl/buffer.h"
#include "gl/context_info.h"
#include "gl/debug_output.h"
#include "gl/framebuffer.h"
#include "gl/gl_error.h"
#include "gl/handle.h"
#include "gl/program.h"
#include "gl/readback.h"
#include "gl/shader_source.h"
#include "gl/stage_clock.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
