// The located-ends solve: rows, space and ends fitted to each other by moving the ends.
#include "located_ends.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "contact.hpp"
#include "contact_end.hpp"
#include "dual_active_set.hpp"
#include "edge.hpp"

namespace plate {

namespace {

// An end of the contact: its angle and the side on which the plate is free (-1: smaller angles).
struct End {
  double theta, sigma;
};
std::vector<End> ends_of(const ContactArcs& c) {
  std::vector<End> out;
  for (const auto& [begin, end] : c.arcs) out.push_back({begin, -1}), out.push_back({end, 1});
  return out;
}

// The gap w - phi that `field` leaves beyond end e, from a quarter to six cells, and the move of the
// end that its fit asks for (end_shift, at most half a cell), as an angle. The fit is an expansion
// in the move over the distance, so it holds only for an end put within a fraction of a cell of
// its place; where the gap is not an end's, the end is moved half a cell: on, if the plate still
// lies on the rim in the first cell beyond it, back if the gap is open there already.
double move_of(const Problem& p, const PlateField& field, const End& e) {
  const EdgeCurve& c = p.scene.edge;
  const double h = p.grid.h;
  std::vector<double> at, gap;
  for (int i = 0; i < 80; ++i) {
    const double s = (0.25 + 5.75 * i / 79.0) * h, th = e.theta + e.sigma * s / c.r;
    const double x = c.cx + c.r * std::cos(th), y = c.cy + c.r * std::sin(th);
    at.push_back(s), gap.push_back(field.at(x, y).w - obstacle_on_edge(p.scene.obstacle, x, y, -std::cos(th), -std::sin(th), h));
  }
  double shift;
  try {
    shift = std::clamp(end_shift(at, gap), -h / 2, h / 2);
  } catch (const std::invalid_argument&) {
    const double first = *std::max_element(gap.begin(), gap.begin() + 11);  // s up to about a cell
    shift = first < 1e-3 * gap.back() ? h / 2 : -h / 2;
  }
  return e.sigma * shift / c.r;
}

// Each arc at least four cells long, and each gap between arcs at least eight (the points of the
// ends on either side take four each).
void check_arcs(const ContactArcs& c, double cell) {
  std::vector<std::pair<double, double>> arcs = c.arcs;
  std::sort(arcs.begin(), arcs.end());
  for (size_t i = 0; i < arcs.size(); ++i) {
    const auto& [begin, end] = arcs[i];
    const double next = i + 1 < arcs.size() ? arcs[i + 1].first : arcs[0].first + 2 * M_PI;
    std::ostringstream m;
    if (end - begin < 4 * cell) m << "the contact arc [" << begin << ", " << end << "] is shorter than four cells";
    else if (next - end < 8 * cell) m << "the gap after the contact arc [" << begin << ", " << end << "] is shorter than eight cells";
    if (!m.str().empty()) throw std::invalid_argument(m.str() + ": its ends cannot be carried apart");
  }
}

}  // namespace

void lay_out_for_ends(Problem& p, const ContactArcs& contact, double dense, double skip) {
  const double h = p.grid.h, cell = h / p.scene.edge.r;
  RimLayout L = layout_for(contact, 0, 2 * cell, 4 * cell, edge_points(p.scene.edge, h).theta, 1e-14);
  for (const End& e : ends_of(contact)) {
    auto beyond = [&](double t) { return std::remainder(t - e.theta, 2 * M_PI) * e.sigma; };
    // A lattice point a hair beyond the end would bear the load the dense points share.
    L.points.erase(std::remove_if(L.points.begin(), L.points.end(), [&](double t) { return beyond(t) > 0 && beyond(t) < 4.01 * cell; }),
                   L.points.end());
    for (int i = 1; i <= 4 * dense; ++i)
      if (i >= skip * dense) L.points.push_back(std::fmod(e.theta + e.sigma * i * cell / dense + 4 * M_PI, 2 * M_PI));
  }
  std::sort(L.points.begin(), L.points.end());
  lay_out_rim(p, L);
}

EndsSolve solve_located_ends(const Scene& scene, int n, ContactArcs contact, const ExactOptions& o, const EndsOptions& opt) {
  if (!scene.cylinder) throw std::invalid_argument("--obstacle: the located ends need the cylinder's scene");
  if (contact.whole || contact.arcs.empty()) throw std::invalid_argument("the contact has no ends: it is the whole rim, or nothing");
  if (!(opt.inner > 0 && opt.inner < opt.outer)) throw std::invalid_argument("EndsOptions: the cut-off needs 0 < inner < outer");
  if (!(opt.dense >= 1) || !(opt.settled > 0) || opt.max_moves < 0)
    throw std::invalid_argument("EndsOptions: dense >= 1, settled > 0 and max_moves >= 0 are needed");
  SamplingSpec spec{SamplingKind::Edge, EdgeRows{}};
  spec.enrich = opt.enrich;
  const Grid g = scene.grid(n);
  const double cell = g.h / scene.edge.r;
  EndsSolve out;
  for (out.moves = 0; out.moves <= opt.max_moves; ++out.moves) {
    check_arcs(contact, cell);
    Problem p = make_problem(scene, g, spec);
    lay_out_for_ends(p, contact, opt.dense, 0);
    std::vector<ContactEnd> ends;
    std::vector<EndField> fields;
    for (const End& e : ends_of(contact))
      for (EndField f : {EndField::Gap32, EndField::Gap52}) {
        ends.push_back({scene.edge.cx, scene.edge.cy, scene.edge.r, e.theta, e.sigma, opt.inner, opt.outer});
        fields.push_back(f);
      }
    attach_ends(p, ends, fields);
    out.result = solve_exact_rows(p, o, NodeSet{}, RowExchange{}, nullptr);
    out.problem = std::move(p);
    if (!out.result.converged) return out;
    const PlateField field(out.problem, out.result.w);
    double largest = 0;
    ContactArcs moved = contact;
    for (size_t a = 0; a < contact.arcs.size(); ++a) {
      const double d0 = move_of(out.problem, field, {contact.arcs[a].first, -1});
      const double d1 = move_of(out.problem, field, {contact.arcs[a].second, 1});
      auto& [begin, end] = moved.arcs[a];
      begin += d0, end += d1;
      const double turns = std::floor(begin / (2 * M_PI)) * 2 * M_PI;  // begin back in [0, 2 pi)
      begin -= turns, end -= turns;
      largest = std::max({largest, std::abs(d0), std::abs(d1)});
    }
    if (largest <= opt.settled) {
      out.settled = true;
      break;
    }
    contact = moved;
  }
  const Problem& p = out.problem;
  const Sampling& s = p.sampling;
  for (size_t k = 0; k < p.ends.size(); k += 2) {
    const ContactEnd& e = p.ends[k];
    int pushing = 0;
    double nearest = 0;
    for (int r = 0; r < s.edge_size(); ++r) {
      const double beyond = std::remainder(s.edge.theta[r] - e.theta, 2 * M_PI) * e.sigma / cell;
      if (!s.rim_rows[r].point() || beyond <= 0 || beyond > 4.01 || !(out.result.lambda[s.edge_begin + r] > 0)) continue;
      if (!pushing++ || beyond < nearest) nearest = beyond;
    }
    out.pushing.push_back(pushing), out.nearest_push.push_back(nearest);
  }
  return out;
}

}  // namespace plate
