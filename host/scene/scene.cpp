#include "scene/scene.h"

namespace rc {

void Scene::add_shape(Shape shape, TriangleMesh triangles) {
    dropped_degenerate += drop_degenerate_triangles(triangles);
    shape.first_triangle = mesh.triangle_count();
    shape.triangle_count = triangles.triangle_count();
    mesh.append(triangles);
    triangle_shape.insert(triangle_shape.end(), triangles.triangle_count(),
                          static_cast<unsigned>(shapes.size()));
    shapes.push_back(std::move(shape));
}

}  // namespace rc
