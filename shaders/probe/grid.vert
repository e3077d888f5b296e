#version 450 core
// probe/grid.vert: a grid of uCells.x by uCells.y cells over the viewport, two triangles a cell, from
// gl_VertexID alone. A corner shared by two cells is computed by the same expression in both, so the
// triangles meet exactly and cover every pixel once.
uniform ivec2 uCells;

void main() {
    int cell = gl_VertexID / 6;
    int corner = gl_VertexID % 6;
    // Triangles (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1) of the cell.
    const ivec2 offsets[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
    ivec2 at = ivec2(cell % uCells.x, cell / uCells.x) + offsets[corner];
    gl_Position = vec4(vec2(at) / vec2(uCells) * 2.0 - 1.0, 0.0, 1.0);
}
