// `scallop render HEIGHTS -o PNG`: a ray-traced 3-D picture of a height map, oblique
// light with shadows, colour bar, box with ticks (tools/run/render_run.h,
// tools/render/render_png.h). Added to the command line by addRenderCommand (command.h).
#pragma once
