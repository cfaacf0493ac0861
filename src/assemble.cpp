// Assembly by stencil. Every element is the same square, so the block coupling two nodes depends
// only on their offset (di, dj) in {-1, 0, 1}^2 and on which of the elements around them exist:
// we write the sparse matrix column by column, in order, with no triplets and no searching.
// This is the usual element loop with the loop over elements done once for all columns.
#include "assemble.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "gauss.hpp"

namespace plate {

namespace {
using Block = Eigen::Matrix4d;

// parts[aqx][aqy][di + 1][dj + 1](a, b): what one element adds to the coupling of component a at
// node Q + (di, dj) with component b at node Q, when Q is the element's corner (aqx, aqy). Inside
// the grid the four elements around Q all exist and these sum to the familiar stencil; on a
// mirror line only the elements on the grid's side do.
using Parts = std::array<std::array<std::array<std::array<Block, 3>, 3>, 2>, 2>;
Parts stencil_parts(const Matrix16& element) {
  Parts parts;
  for (int aqx = 0; aqx < 2; ++aqx)
    for (int aqy = 0; aqy < 2; ++aqy)
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          const int apx = aqx + di, apy = aqy + dj;
          Block& b = parts[aqx][aqy][di + 1][dj + 1];
          b.setZero();
          if (apx < 0 || apx > 1 || apy < 0 || apy > 1) continue;
          b = element.block<4, 4>(4 * (apx + 2 * apy), 4 * (aqx + 2 * aqy));
        }
  return parts;
}

// The coupling block of node (qi + di, qj + dj) with node (qi, qj), summed over the elements of
// the grid that contain both.
Block coupling(const Grid& g, const Parts& parts, int qi, int qj, int di, int dj) {
  Block sum = Block::Zero();
  for (int aqx = 0; aqx < 2; ++aqx)
    for (int aqy = 0; aqy < 2; ++aqy) {
      const int ex = qi - aqx, ey = qj - aqy;  // the element with Q at its corner (aqx, aqy)
      if (ex < 0 || ex >= g.nx || ey < 0 || ey >= g.ny) continue;
      sum += parts[aqx][aqy][di + 1][dj + 1];
    }
  return sum;
}
}  // namespace

SpMat assemble_matrix(const Grid& g, const Matrix16& element) {
  const Parts parts = stencil_parts(element);
  const Block centre = coupling(make_grid(2), parts, 1, 1, 0, 0);  // a node with all four elements around it
  const int n = g.unknowns();
  SpMat A(n, n);
  A.reserve(static_cast<Eigen::Index>(n) * 36);
  for (int qj = 1; qj <= g.ny; ++qj)
    for (int qi = 1; qi <= g.nx; ++qi) {
      if (!g.is_interior(qi, qj)) continue;
      std::array<std::array<Block, 3>, 3> blocks;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) blocks[di + 1][dj + 1] = coupling(g, parts, qi, qj, di, dj);
      for (int b = 0; b < 4; ++b) {
        const int col = 4 * g.node(qi, qj) + b;
        A.startVec(col);
        if (g.pinned(qi, qj, b)) {  // held at zero: decoupled, with the size of an ordinary diagonal
          A.insertBack(col, col) = centre(b, b);
          continue;
        }
        // Neighbours in (dj, di) order have increasing node numbers, so rows come sorted.
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            if (!g.is_interior(qi + di, qj + dj)) continue;
            const int row0 = 4 * g.node(qi + di, qj + dj);
            for (int a = 0; a < 4; ++a)
              if (!g.pinned(qi + di, qj + dj, a)) A.insertBack(row0 + a, col) = blocks[di + 1][dj + 1](a, b);
          }
      }
    }
  A.finalize();
  return A;
}

VectorXd assemble_load(const Grid& g, const Field& f, const char* name) {
  const Quadrature1D q = gauss_legendre(4);
  VectorXd F = VectorXd::Zero(g.unknowns());
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex) {
      const auto dofs = g.element_dofs(ex, ey);
      for (size_t i = 0; i < q.points.size(); ++i)
        for (size_t j = 0; j < q.points.size(); ++j) {
          const double x = g.x(ex) + q.points[i] * g.h, y = g.y(ey) + q.points[j] * g.h;
          const double fx = f(x, y);
          if (!std::isfinite(fx))
            throw std::invalid_argument(std::string(name) + " is not finite at (" + std::to_string(x) + ", " +
                                        std::to_string(y) + "): " + std::to_string(fx));
          const Vector16 v = bfs_basis(q.points[i], q.points[j], g.h).v;
          const double wq = q.weights[i] * q.weights[j] * g.h * g.h * fx;
          for (int k = 0; k < 16; ++k)
            if (dofs[k] >= 0) F[dofs[k]] += wq * v[k];
        }
    }
  return F;
}

}  // namespace plate
