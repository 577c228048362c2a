// Per-step records of the contact nodes (edp/problems/sleeve/sleeve-2d.idp, time-loop.idp): what
// the 2D sleeve's script kept in loops over the contact nodes, each iteration costing about 800
// instructions of FreeFEM's interpreter, every step. Plain loops over arrays; reactions are
// interleaved (normal, tangential) per node.
#pragma once

#include <cmath>
#include <cstddef>

namespace sma::contact_history {

// The nodes touching: normal reaction > 0.
inline long touching(const double* reactions, std::size_t nodes) {
  long count = 0;
  for (std::size_t i = 0; i < nodes; ++i) count += reactions[2 * i] > 0;
  return count;
}

// Each node's highest pressure so far and the step it was reached at (peakStep set where the
// pressure exceeds the old peak; the peak then max(peak, pressure), as FreeFEM's max: the first
// when it is greater, else the second).
inline void record_peaks(const double* pressure, std::size_t nodes, long step, double* peak, long* peakStep) {
  for (std::size_t i = 0; i < nodes; ++i) {
    if (pressure[i] > peak[i]) peakStep[i] = step;
    peak[i] = peak[i] > pressure[i] ? peak[i] : pressure[i];
  }
}

// The last step each node slipped: |slip| above noise while touching (normal reaction > 0).
inline void record_slip(const double* slip, const double* reactions, std::size_t nodes, double noise, long step,
                        long* lastSlipStep) {
  for (std::size_t i = 0; i < nodes; ++i)
    if (std::abs(slip[i]) > noise && reactions[2 * i] > 0) lastSlipStep[i] = step;
}

// The sleeve's default heat condition at the contact nodes (edp/problems/sleeve/time-loop.idp,
// SleeveHeatCondition): exchange coefficient gContact where the node presses on the pipe (normal
// reaction > 0), gPipe where it does not, with the pipe at Tpipe; node[i] is the heat node of
// contact node i. Returns how many press.
inline long heat_exchange(const long* node, const double* reactions, std::size_t nodes, double gContact, double gPipe,
                          double Tpipe, double* g, double* Text) {
  long pressing = 0;
  for (std::size_t i = 0; i < nodes; ++i) {
    const bool presses = reactions[2 * i] > 0;
    g[node[i]] = presses ? gContact : gPipe;
    Text[node[i]] = Tpipe;
    pressing += presses;
  }
  return pressing;
}

// points.csv's columns at probe points (sleeve-2d.idp: near, top, far), appended to row: per
// point its vertex's temperature, its contact node's pressure and gap, the gap n.u (- the elastic
// pipe's normal motion there) + the initial gap, in the script's order of operations
// ((nx ux + ny uy) - motion) + gap0 (node i's normal (nx, ny) and initial gap0 given per point).
struct ProbePoint {
  long node, vertex;
  double nx, ny, gap0;
};
inline void probe_columns(const ProbePoint* points, std::size_t count, const double* T, const double* pressure,
                          const double* u, const double* pipeNormalMotion, double* row) {
  for (std::size_t p = 0; p < count; ++p) {
    const ProbePoint& q = points[p];
    const double normal = q.nx * u[2 * q.vertex] + q.ny * u[2 * q.vertex + 1];
    row[3 * p] = T[q.vertex];
    row[3 * p + 1] = pressure[q.node];
    row[3 * p + 2] = pipeNormalMotion ? normal - pipeNormalMotion[q.node] + q.gap0 : normal + q.gap0;
  }
}

}  // namespace sma::contact_history
