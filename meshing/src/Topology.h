#pragma once
// The mesher's clean-up steps that need no field (DualContouring.cpp calls them; Mesh.h declares
// the public ones: checkTopology, countDegenerateTriangles, subdividedTopology,
// flipCollinearTriangles).

#include <meshing/Mesh.h>

namespace sdfwb::meshing::detail {

// Cells around a point where the surface meets a grid line (a cone's apex on the axis) can put
// their vertices at the very same position; the quads between them then hold triangles of zero
// area. Vertices that share a triangle and a position (to `tolerance`, a millionth of a cell: 4e-19 apart is
// a triangle of zero area in float) become one, the triangles that
// repeat a vertex then go (each such merge is the collapse of an edge of length zero, which keeps
// the surface closed and its orientation), and vertices no triangle uses any more are dropped.
// A collapse that would pinch the surface (the two vertices have a neighbour in common that no
// triangle of their edge holds: both sides of a split face, splitJoinedFaces) is not made; the
// two are moved a hundredth of the way towards the middle of their other neighbours instead, which
// parts them. Meshes without such triangles (nearly all) are left as they are.
void weldCoincidentVertices(Mesh& mesh, float tolerance);

// Triangles of zero area whose three vertices lie on one line that flipCollinearTriangles could not
// mend (the edge a flip would make exists already: a knot of vertices a ten-thousandth of a cell
// apart, where a flat cap at the bounds meets a pinch of a fractal): the middle vertex moves a
// little towards the middle of its neighbours, off the line, where no triangle around it turns
// over or loses its area. Returns the vertices moved.
std::uint64_t nudgeCollinearVertices(Mesh& mesh);

} // namespace sdfwb::meshing::detail
