#include "rasterizer.h"

#include <memory>
#include <string>

#include <GL/osmesa.h>
#include <GL/gl.h>

#include "subdiv/core/error.h"

namespace subdiv::render {

namespace {

struct ContextDeleter {
  void operator()(osmesa_context* context) const { OSMesaDestroyContext(context); }
};
using Context = std::unique_ptr<osmesa_context, ContextDeleter>;

void set_lights(const RenderStyle& style) {
  glEnable(GL_LIGHTING);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  const GLfloat ambient[] = {0.18F, 0.18F, 0.18F, 1.0F};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  // A key light from the upper left of the camera and a weaker one from the
  // camera itself, both directional and fixed to the view.
  const GLfloat key_direction[] = {-0.45F, 0.55F, 0.70F, 0.0F};
  const GLfloat key[] = {0.75F, 0.75F, 0.75F, 1.0F};
  const GLfloat head_direction[] = {0.0F, 0.0F, 1.0F, 0.0F};
  const GLfloat head[] = {0.30F, 0.30F, 0.30F, 1.0F};
  const GLfloat specular[] = {0.25F, 0.25F, 0.25F, 1.0F};
  glLightfv(GL_LIGHT0, GL_POSITION, key_direction);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, key);
  glLightfv(GL_LIGHT0, GL_SPECULAR, specular);
  glLightfv(GL_LIGHT1, GL_POSITION, head_direction);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, head);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  const GLfloat front[] = {style.surface.r, style.surface.g, style.surface.b, 1.0F};
  const GLfloat back[] = {style.back.r, style.back.g, style.back.b, 1.0F};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, front);
  glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, back);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0F);
}

void draw_scene(const Scene& scene, const RenderStyle& style, const Camera& camera, int samples) {
  glClearColor(style.background.r, style.background.g, style.background.b, 1.0F);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(camera.projection.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  set_lights(style);  // in eye coordinates: fixed to the camera
  glLoadMatrixd(camera.view.data());
  glShadeModel(GL_SMOOTH);
  glEnable(GL_NORMALIZE);
  // The faces sit slightly behind their edges, so that lines drawn on the
  // surface are not hidden by it.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0F, 1.0F);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, scene.positions.data());
  glNormalPointer(GL_FLOAT, 0, scene.normals.data());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(scene.triangles.size()), GL_UNSIGNED_INT, scene.triangles.data());
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisable(GL_LIGHTING);
  for (const LineSet& set : scene.lines) {
    glLineWidth(set.width * static_cast<float>(samples));
    glColor3f(set.colour.r, set.colour.g, set.colour.b);
    glVertexPointer(3, GL_FLOAT, 0, set.ends.data());
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(set.ends.size() / 3));
  }
  glDisableClientState(GL_VERTEX_ARRAY);
  glFinish();
}

// Box-filters the supersampled RGBA buffer (bottom row first) into RGB,
// top row first.
Image downsample(const std::vector<GLubyte>& rgba, int width, int height, int samples) {
  Image image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 3)};
  const int big_width = width * samples;
  const int area = samples * samples;
  for (int y = 0; y < height; ++y) {
    const int source_row = (height - 1 - y) * samples;
    for (int x = 0; x < width; ++x)
      for (int k = 0; k < 3; ++k) {
        int sum = 0;
        for (int sy = 0; sy < samples; ++sy)
          for (int sx = 0; sx < samples; ++sx)
            sum += rgba[(static_cast<std::size_t>(source_row + sy) * big_width + x * samples + sx) * 4 + k];
        image.rgb[(static_cast<std::size_t>(y) * width + x) * 3 + k] = static_cast<std::uint8_t>((sum + area / 2) / area);
      }
  }
  return image;
}

}  // namespace

Image rasterize(const Scene& scene, const RenderStyle& style) {
  if (style.width < 1 || style.height < 1 || style.width > kMaxImageSide || style.height > kMaxImageSide)
    throw InvalidInputError("image size " + std::to_string(style.width) + "x" + std::to_string(style.height) +
                            " is outside 1x1 .. " + std::to_string(kMaxImageSide) + "x" + std::to_string(kMaxImageSide));
  const int samples = std::max(1, style.supersample);
  Context context(OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr));
  if (!context) throw Error("cannot create Mesa's off-screen rendering context (OSMesa)");
  int max_width = 0, max_height = 0;
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &max_width);
  OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &max_height);
  const int width = style.width * samples, height = style.height * samples;
  if (width > max_width || height > max_height)
    throw InvalidInputError("image size " + std::to_string(style.width) + "x" + std::to_string(style.height) +
                            " with " + std::to_string(samples) + "x" + std::to_string(samples) +
                            " samples exceeds the renderer's " + std::to_string(max_width) + "x" +
                            std::to_string(max_height));
  std::vector<GLubyte> rgba(static_cast<std::size_t>(width) * height * 4);
  if (!OSMesaMakeCurrent(context.get(), rgba.data(), GL_UNSIGNED_BYTE, width, height))
    throw Error("cannot attach the image buffer to Mesa's off-screen context");
  glViewport(0, 0, width, height);
  draw_scene(scene, style, frame_sphere(scene.centre, scene.radius, style.view, width, height), samples);
  if (const GLenum status = glGetError(); status != GL_NO_ERROR)
    throw Error("Mesa's off-screen renderer reported OpenGL error " + std::to_string(status));
  return downsample(rgba, style.width, style.height, samples);
}

}  // namespace subdiv::render
