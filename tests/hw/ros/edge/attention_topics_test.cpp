// The belief and marker messages of oasis-ros (hw/ros/attention_topics.hpp), built without a
// roscore: against the Go1 catalog linked into the project, and against two small catalogs made
// here for the partitions it does not have (blocks of several cells, a BSP).
//
// Compiles as C++17, like the edge it tests (ROS 1's message headers).
#include "ros/attention_topics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "go1_treat_catalog.hpp"
#include "oasis/rt/bsp_locator.hpp"
#include "oasis/rt/grid_locator.hpp"

namespace oasis::hw::ros_node {
namespace {

using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

const rt::CatalogView& go1() {
  return go1_treat::catalog();
}

const std::string kFrame = "base_link";
const ros::Time kStamp(12.5);

// A step of the loop: both people seen where the state puts them, unless changed after.
log::StepRecord step_at(std::vector<double> state, std::uint32_t abstraction) {
  log::StepRecord record;
  record.state = std::move(state);
  record.abstraction = abstraction;
  record.abstraction_name = abstraction == 0 ? "human1_holds_treat" : "human2_holds_treat";
  record.belief = {0.7, 0.3};
  for (std::size_t k = 0; k < 2 && 2 * k + 1 < record.state.size(); ++k) {
    record.humans[k].seen = true;
    record.humans[k].x_m = record.state[2 * k];
    record.humans[k].y_m = record.state[2 * k + 1];
    record.humans[k].confidence = 0.9;
  }
  return record;
}

MarkerArray markers_of(const rt::CatalogView& catalog, const log::StepRecord& record,
                       const ReachRegion& reach = ReachRegion{}) {
  return attention_markers(catalog, record, reach, kFrame, kStamp);
}

// The marker in slot (ns, id) if it is drawn (action ADD), else null.
const Marker* drawn(const MarkerArray& array, const std::string& ns, int id) {
  for (const Marker& m : array.markers)
    if (m.ns == ns && m.id == id && m.action == Marker::ADD) return &m;
  return nullptr;
}

std::size_t drawn_in(const MarkerArray& array, const std::string& ns) {
  return static_cast<std::size_t>(
      std::count_if(array.markers.begin(), array.markers.end(),
                    [&](const Marker& m) { return m.ns == ns && m.action == Marker::ADD; }));
}

bool in_triangle(double x, double y, const geometry_msgs::Point& a, const geometry_msgs::Point& b,
                 const geometry_msgs::Point& c) {
  const auto side = [&](const geometry_msgs::Point& p, const geometry_msgs::Point& q) {
    return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
  };
  const double d1 = side(a, b), d2 = side(b, c), d3 = side(c, a);
  const double eps = 1e-12;
  const bool has_neg = d1 < -eps || d2 < -eps || d3 < -eps;
  const bool has_pos = d1 > eps || d2 > eps || d3 > eps;
  return !(has_neg && has_pos);
}

bool triangles_contain(const Marker& m, double x, double y) {
  for (std::size_t i = 0; i + 2 < m.points.size(); i += 3)
    if (in_triangle(x, y, m.points[i], m.points[i + 1], m.points[i + 2])) return true;
  return false;
}

bool segments_touch(const Marker& m, double x, double y) {
  const double eps = 1e-9;
  for (std::size_t i = 0; i + 1 < m.points.size(); i += 2) {
    const geometry_msgs::Point& a = m.points[i];
    const geometry_msgs::Point& b = m.points[i + 1];
    const double cross = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
    if (std::fabs(cross) > eps) continue;
    if (x >= std::min(a.x, b.x) - eps && x <= std::max(a.x, b.x) + eps &&
        y >= std::min(a.y, b.y) - eps && y <= std::max(a.y, b.y) + eps)
      return true;
  }
  return false;
}

// The block of `state` in abstraction `a`, as the filter finds it.
std::uint32_t block_of(const rt::CatalogView& catalog, std::uint32_t a,
                       const std::vector<double>& state) {
  const rt::AbstractionView& abs = catalog.abstractions[a];
  const std::uint32_t cell =
      rt::locate_partition_cell(abs.grid, abs.bsp, state.data(), state.size());
  return cell == rt::kOutsideCell ? abs.outside_block : abs.cell_block[cell];
}

// The breakpoints of the grid axis over state variable `variable`.
std::vector<double> breaks_of(const rt::GridView& grid, std::uint32_t variable) {
  for (std::uint32_t i = 0; i < grid.dimension; ++i)
    if (grid.axes[i] == variable)
      return {grid.breaks + grid.break_begin[i], grid.breaks + grid.break_begin[i + 1]};
  return {};
}

// [lo, hi] of the grid interval holding v.
std::pair<double, double> interval_of(const std::vector<double>& t, double v) {
  for (std::size_t k = 0; k + 1 < t.size(); ++k)
    if (v >= t[k] && v < t[k + 1]) return {t[k], t[k + 1]};
  return {t[t.size() - 2], t.back()};
}

// ---- context_names and belief_message ----

TEST(ContextNames, AreTheCatalogsContextsInItsOrder) {
  EXPECT_EQ(context_names(go1()),
            (std::vector<std::string>{"human1_holds_treat", "human2_holds_treat"}));
  EXPECT_TRUE(context_names(rt::CatalogView{}).empty());
}

TEST(BeliefMessage, NamesEachProbabilityInTheLayout) {
  const auto names = context_names(go1());
  const log::StepRecord record = step_at({1.0, 0.5, 2.0, -1.0}, 0);
  const std_msgs::Float64MultiArray message = belief_message(record, names);

  ASSERT_EQ(message.layout.dim.size(), 3u);
  EXPECT_EQ(message.layout.dim[0].label, "contexts");
  EXPECT_EQ(message.layout.dim[0].size, 2u);
  EXPECT_EQ(message.layout.dim[0].stride, 2u);
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(message.layout.dim[1 + i].label, names[i]);
    EXPECT_EQ(message.layout.dim[1 + i].size, 1u);
    EXPECT_EQ(message.layout.dim[1 + i].stride, 1u);
  }
  EXPECT_EQ(message.layout.data_offset, 0u);
  EXPECT_EQ(message.data, record.belief);
  double sum = 0.0;
  for (const double p : message.data)
    sum += p;
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

TEST(BeliefMessage, LabelsNumbersBeyondTheNamesByIndex) {
  log::StepRecord record = step_at({1.0, 0.5, 2.0, -1.0}, 0);
  record.belief = {0.5, 0.25, 0.25};
  const std_msgs::Float64MultiArray message = belief_message(record, context_names(go1()));
  ASSERT_EQ(message.layout.dim.size(), 4u);
  EXPECT_EQ(message.layout.dim[0].size, 3u);
  EXPECT_EQ(message.layout.dim[3].label, "2");
  EXPECT_EQ(message.data.size(), 3u);
}

// ---- attention_markers on the Go1 catalog ----

TEST(AttentionMarkers, ShowTheBeliefAsTextWithTheAttendedContextMarked) {
  oasis::hw::log::StepRecord record = step_at({1.03, 0.41, 2.0, -1.0}, 1);
  record.belief = {0.25, 0.75};
  const MarkerArray array = markers_of(go1(), record);
  const auto belief = std::find_if(array.markers.begin(), array.markers.end(),
                                   [](const Marker& m) { return m.ns == "belief"; });
  ASSERT_NE(belief, array.markers.end());
  EXPECT_EQ(belief->type, Marker::TEXT_VIEW_FACING);
  const std::vector<std::string> names = context_names(go1());
  EXPECT_EQ(belief->text, names[0] + "  0.25\n" + names[1] + "  0.75  <- attended");
}

TEST(AttentionMarkers, AreInTheBaseFrameInStableSlots) {
  const MarkerArray full = markers_of(go1(), step_at({1.03, 0.41, 2.0, -1.0}, 0));
  const MarkerArray other = markers_of(go1(), step_at({3.0, -2.0, 0.5, 0.1}, 1));
  const MarkerArray short_state = markers_of(go1(), step_at({1.0, 0.5}, 0));

  std::set<std::string> drawn_namespaces;
  std::set<std::pair<std::string, int>> slots;
  for (const Marker& m : full.markers) {
    EXPECT_EQ(m.header.frame_id, kFrame);
    EXPECT_EQ(m.header.stamp, kStamp);
    EXPECT_EQ(m.lifetime, ros::Duration(0));
    EXPECT_FALSE(m.frame_locked);
    EXPECT_EQ(m.pose.orientation.w, 1.0);
    EXPECT_TRUE(m.action == Marker::ADD || m.action == Marker::DELETE);
    EXPECT_TRUE(slots.emplace(m.ns, m.id).second) << m.ns << " " << m.id << " twice";
    if (m.action == Marker::ADD) drawn_namespaces.insert(m.ns);
  }
  EXPECT_EQ(drawn_namespaces,
            (std::set<std::string>{"belief", "cells", "current_cell", "people", "reach"}));

  // Every step sends the same slots (drawn or deleted), in the same order: rviz replaces them.
  const auto keys = [](const MarkerArray& a) {
    std::vector<std::pair<std::string, int>> k;
    for (const Marker& m : a.markers)
      k.emplace_back(m.ns, m.id);
    return k;
  };
  EXPECT_EQ(keys(full), keys(other));
  EXPECT_EQ(keys(full), keys(short_state));
}

TEST(AttentionMarkers, HighlightTheCurrentBlockAroundTheState) {
  for (std::uint32_t a = 0; a < 2; ++a) {
    SCOPED_TRACE("abstraction " + std::to_string(a));
    const std::vector<double> state = {1.03, 0.41, 2.0, -1.0};
    const MarkerArray array = markers_of(go1(), step_at(state, a));
    const int attended = static_cast<int>(a);  // abstraction i attends to human i+1 only
    const int ignored = 1 - attended;

    const Marker* current = drawn(array, "current_cell", attended);
    ASSERT_NE(current, nullptr);
    EXPECT_EQ(current->type, Marker::TRIANGLE_LIST);
    ASSERT_FALSE(current->points.empty());
    EXPECT_EQ(current->points.size() % 3, 0u);
    const double x = state[2 * a], y = state[2 * a + 1];
    EXPECT_TRUE(triangles_contain(*current, x, y));
    EXPECT_FALSE(triangles_contain(*current, x + 0.15, y));  // cells are about 6 cm
    EXPECT_FALSE(triangles_contain(*current, x, y - 0.15));

    // Every highlighted triangle lies in the current block.
    const std::uint32_t block = block_of(go1(), a, state);
    for (std::size_t i = 0; i + 2 < current->points.size(); i += 3) {
      std::vector<double> s = state;
      s[2 * a] = (current->points[i].x + current->points[i + 1].x + current->points[i + 2].x) / 3;
      s[2 * a + 1] =
          (current->points[i].y + current->points[i + 1].y + current->points[i + 2].y) / 3;
      EXPECT_EQ(block_of(go1(), a, s), block);
    }

    // The other person's slice does not change the abstraction: nothing drawn for it.
    EXPECT_EQ(drawn(array, "cells", ignored), nullptr);
    EXPECT_EQ(drawn(array, "current_cell", ignored), nullptr);
  }
}

TEST(AttentionMarkers, DrawTheBoundariesOfTheCurrentBlock) {
  const std::vector<double> state = {1.03, 0.41, 2.0, -1.0};
  const MarkerArray array = markers_of(go1(), step_at(state, 0));
  const Marker* cells = drawn(array, "cells", 0);
  ASSERT_NE(cells, nullptr);
  EXPECT_EQ(cells->type, Marker::LINE_LIST);
  EXPECT_GT(cells->scale.x, 0.0);
  ASSERT_FALSE(cells->points.empty());
  EXPECT_EQ(cells->points.size() % 2, 0u);
  for (const geometry_msgs::Point& p : cells->points) {
    EXPECT_GE(p.x, 0.0);
    EXPECT_LE(p.x, 5.0);
    EXPECT_GE(p.y, -3.0);
    EXPECT_LE(p.y, 3.0);
  }

  const rt::GridView& grid = go1().abstractions[0].grid;
  const auto [x0, x1] = interval_of(breaks_of(grid, 0), state[0]);
  const auto [y0, y1] = interval_of(breaks_of(grid, 1), state[1]);
  EXPECT_FALSE(segments_touch(*cells, (x0 + x1) / 2, (y0 + y1) / 2));  // the cell's inside
  const std::uint32_t block = block_of(go1(), 0, state);
  int checked = 0;
  // Each side of the current cell: drawn exactly when the neighbour is another block.
  const struct {
    double edge_x, edge_y, beyond_x, beyond_y;
  } sides[] = {{x0, (y0 + y1) / 2, x0 - 0.01, (y0 + y1) / 2},
               {x1, (y0 + y1) / 2, x1 + 0.01, (y0 + y1) / 2},
               {(x0 + x1) / 2, y0, (x0 + x1) / 2, y0 - 0.01},
               {(x0 + x1) / 2, y1, (x0 + x1) / 2, y1 + 0.01}};
  for (const auto& side : sides) {
    std::vector<double> beyond = state;
    beyond[0] = side.beyond_x;
    beyond[1] = side.beyond_y;
    const bool other_block = block_of(go1(), 0, beyond) != block;
    EXPECT_EQ(segments_touch(*cells, side.edge_x, side.edge_y), other_block);
    checked += other_block ? 1 : 0;
  }
  EXPECT_GT(checked, 0);
}

TEST(AttentionMarkers, ShowTheReachRegionAsAGreenFlatCube) {
  for (const ReachRegion& reach : {ReachRegion{}, ReachRegion{1.0, 2.0, -0.5, 0.1}}) {
    const MarkerArray array = markers_of(go1(), step_at({1.0, 0.5, 2.0, -1.0}, 0), reach);
    const Marker* cube = drawn(array, "reach", 0);
    ASSERT_NE(cube, nullptr);
    EXPECT_EQ(cube->type, Marker::CUBE);
    EXPECT_DOUBLE_EQ(cube->pose.position.x, (reach.x_min_m + reach.x_max_m) / 2);
    EXPECT_DOUBLE_EQ(cube->pose.position.y, (reach.y_min_m + reach.y_max_m) / 2);
    EXPECT_DOUBLE_EQ(cube->scale.x, reach.x_max_m - reach.x_min_m);
    EXPECT_DOUBLE_EQ(cube->scale.y, reach.y_max_m - reach.y_min_m);
    EXPECT_GT(cube->scale.z, 0.0);
    EXPECT_LT(cube->scale.z, 0.05);
    EXPECT_GT(cube->color.g, cube->color.r);
    EXPECT_GT(cube->color.g, cube->color.b);
    EXPECT_GT(cube->color.a, 0.0f);
    EXPECT_LT(cube->color.a, 1.0f);
  }
}

TEST(AttentionMarkers, ShowThePeopleWherePerceptionSawThem) {
  log::StepRecord record = step_at({1.0, 0.5, 2.0, -1.0}, 0);
  record.humans[0].x_m = 1.2;  // perception's reading, not the state the filter was given
  record.humans[0].y_m = 0.3;
  const MarkerArray array = markers_of(go1(), record);

  const Marker* red = drawn(array, "people", 0);
  ASSERT_NE(red, nullptr);
  EXPECT_EQ(red->type, Marker::SPHERE);
  EXPECT_DOUBLE_EQ(red->pose.position.x, 1.2);
  EXPECT_DOUBLE_EQ(red->pose.position.y, 0.3);
  EXPECT_GT(red->color.r, 0.5f);
  EXPECT_LT(red->color.g, 0.5f);
  EXPECT_LT(red->color.b, 0.5f);

  const Marker* yellow = drawn(array, "people", 1);
  ASSERT_NE(yellow, nullptr);
  EXPECT_DOUBLE_EQ(yellow->pose.position.x, 2.0);
  EXPECT_DOUBLE_EQ(yellow->pose.position.y, -1.0);
  EXPECT_GT(yellow->color.r, 0.5f);
  EXPECT_GT(yellow->color.g, 0.5f);
  EXPECT_LT(yellow->color.b, 0.5f);

  for (int k = 0; k < 2; ++k) {
    const Marker* label = drawn(array, "people", k + 2);
    ASSERT_NE(label, nullptr);
    EXPECT_EQ(label->type, Marker::TEXT_VIEW_FACING);
    EXPECT_EQ(label->text, "human " + std::to_string(k + 1));
    EXPECT_GT(label->scale.z, 0.0);
  }
}

TEST(AttentionMarkers, GreyAnUnseenPersonWhereTheFilterHoldsThem) {
  log::StepRecord record = step_at({1.0, 0.5, 2.0, -1.0}, 0);
  record.humans[1].seen = false;
  record.humans[1].x_m = 9.0;  // meaningless when not seen
  const MarkerArray array = markers_of(go1(), record);
  const Marker* held = drawn(array, "people", 1);
  ASSERT_NE(held, nullptr);
  EXPECT_DOUBLE_EQ(held->pose.position.x, 2.0);
  EXPECT_DOUBLE_EQ(held->pose.position.y, -1.0);
  EXPECT_EQ(held->color.r, held->color.g);
  EXPECT_EQ(held->color.g, held->color.b);
  const Marker* label = drawn(array, "people", 3);
  ASSERT_NE(label, nullptr);
  EXPECT_EQ(label->text, "human 2 (not seen)");
  ASSERT_NE(drawn(array, "people", 0), nullptr);  // human 1 still seen, in red
  EXPECT_NE(drawn(array, "people", 0)->color.r, drawn(array, "people", 0)->color.g);

  // With no state to hold them at, an unseen person is not drawn.
  record.state = {1.0, 0.5};
  const MarkerArray without_state = markers_of(go1(), record);
  EXPECT_EQ(drawn(without_state, "people", 1), nullptr);
  EXPECT_EQ(drawn(without_state, "people", 3), nullptr);
  EXPECT_NE(drawn(without_state, "people", 0), nullptr);
}

TEST(AttentionMarkers, DrawNoCellsForAShortStateOrAnUnexpectedCatalog) {
  struct Case {
    std::string what;
    const rt::CatalogView* catalog;
    log::StepRecord record;
    std::size_t people;  // drawn people markers: a sphere and a label per person it can place
  };
  const rt::CatalogView empty{};
  log::StepRecord bad_index = step_at({1.0, 0.5, 2.0, -1.0}, 0);
  bad_index.abstraction = 7;
  const Case cases[] = {{"short state", &go1(), step_at({1.0, 0.5}, 0), 2},
                        {"no state", &go1(), step_at({}, 1), 0},
                        {"abstraction out of range", &go1(), bad_index, 4},
                        {"empty catalog", &empty, step_at({1.0, 0.5, 2.0, -1.0}, 0), 4}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    MarkerArray array;
    EXPECT_NO_THROW(array = markers_of(*c.catalog, c.record));
    EXPECT_EQ(drawn_in(array, "cells"), 0u);
    EXPECT_EQ(drawn_in(array, "current_cell"), 0u);
    EXPECT_NE(drawn(array, "reach", 0), nullptr);
    EXPECT_EQ(drawn_in(array, "people"), c.people);
  }
}

TEST(AttentionMarkers, StayBounded) {
  for (std::uint32_t a = 0; a < 2; ++a) {
    for (const auto& state :
         {std::vector<double>{0.0, -3.0, 5.0, 3.0}, std::vector<double>{2.5, 0.0, 2.5, 0.0},
          std::vector<double>{6.0, 4.0, -1.0, 0.0}}) {
      std::size_t points = 0;
      for (const Marker& m : markers_of(go1(), step_at(state, a)).markers)
        points += m.points.size();
      EXPECT_LE(points, 4500u);
    }
  }
}

TEST(AttentionMarkers, DrawNothingOfACellOutsideTheDomain) {
  // Human 1 beside the robot, outside the catalog's domain: the outside block, no highlight,
  // but the slice's cells are still there.
  const MarkerArray array = markers_of(go1(), step_at({-1.0, 0.0, 2.0, -1.0}, 0));
  EXPECT_NE(drawn(array, "cells", 0), nullptr);
  EXPECT_EQ(drawn(array, "current_cell", 0), nullptr);
}

// ---- small catalogs: a block of several cells, and a BSP ----

// One abstraction over (x1, y1) in [0, 2] x [-1, 1]; the other fields as a grid catalog has them.
struct SmallCatalog {
  std::uint32_t axes[2] = {0, 1};
  std::uint32_t break_begin[3] = {0, 3, 6};
  double breaks[6] = {0.0, 1.0, 2.0, -1.0, 0.0, 1.0};
  std::vector<std::uint32_t> cell_block;
  double block_reward[4] = {0, 0, 0, 0};
  std::uint32_t policy[4] = {0, 0, 0, 0};
  double value[4] = {0, 0, 0, 0};
  double reward[4] = {0, 0, 0, 0};
  const char* action_names[1] = {"stop"};
  double switching[1] = {1.0};
  double prior[1] = {1.0};
  rt::AbstractionView abs;
  rt::CatalogView catalog;

  explicit SmallCatalog(std::vector<std::uint32_t> blocks, std::uint32_t num_blocks)
      : cell_block(std::move(blocks)) {
    abs.context = "small";
    abs.num_blocks = num_blocks;
    abs.block_reward = block_reward;
    abs.reward = reward;
    abs.policy = policy;
    abs.value = value;
    abs.grid = rt::GridView{2, axes, break_begin, breaks};
    abs.cell_block = cell_block.data();
    abs.outside_block = num_blocks - 1;
    catalog.name = "small";
    catalog.num_actions = 1;
    catalog.action_names = action_names;
    catalog.num_abstractions = 1;
    catalog.switching = switching;
    catalog.prior = prior;
    catalog.abstractions = &abs;
    catalog.state_dimension = 4;
  }
};

TEST(AttentionMarkers, MergeTheCellsOfOneBlock) {
  // Cells (x, y) row-major: 0 = [0,1)x[-1,0), 1 = [0,1)x[0,1], 2 = [1,2]x[-1,0), 3 = [1,2]x[0,1];
  // cells 0 and 1 are one block.
  const SmallCatalog small({0, 0, 1, 2}, 4);
  const MarkerArray array = markers_of(small.catalog, step_at({0.5, 0.5, 0.0, 0.0}, 0));

  const Marker* current = drawn(array, "current_cell", 0);
  ASSERT_NE(current, nullptr);
  EXPECT_TRUE(triangles_contain(*current, 0.5, 0.5));
  EXPECT_TRUE(triangles_contain(*current, 0.5, -0.5));
  EXPECT_FALSE(triangles_contain(*current, 1.5, 0.5));
  EXPECT_FALSE(triangles_contain(*current, 1.5, -0.5));

  const Marker* cells = drawn(array, "cells", 0);
  ASSERT_NE(cells, nullptr);
  EXPECT_FALSE(segments_touch(*cells, 0.5, 0.0));  // inside the block
  EXPECT_TRUE(segments_touch(*cells, 1.5, 0.0));   // between blocks 1 and 2
  EXPECT_TRUE(segments_touch(*cells, 1.0, 0.5));
  EXPECT_TRUE(segments_touch(*cells, 1.0, -0.5));
  EXPECT_TRUE(segments_touch(*cells, 0.0, 0.5));  // the outline
  EXPECT_TRUE(segments_touch(*cells, 2.0, -0.5));
  EXPECT_TRUE(segments_touch(*cells, 0.5, 1.0));
}

TEST(AttentionMarkers, SampleABspPartition) {
  // One grid cell, split by the BSP at x1 = 1: cell 0 for x1 <= 1, cell 1 beyond.
  SmallCatalog small({0, 1}, 3);
  small.break_begin[1] = 2;
  small.break_begin[2] = 4;
  const double breaks[4] = {0.0, 2.0, -1.0, 1.0};
  std::copy(breaks, breaks + 4, small.breaks);
  const double normal[6] = {1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const double bound[3] = {1.0, 0.0, 0.0};
  const std::uint32_t below[3] = {1, 0, 0};
  const std::uint32_t above[3] = {2, 0, 0};
  const std::uint32_t cell[3] = {rt::kInternalNode, 0, 1};
  small.abs.bsp = rt::BspView{3, 2, normal, bound, below, above, cell};

  const MarkerArray array = markers_of(small.catalog, step_at({0.5, 0.2, 0.0, 0.0}, 0));
  const Marker* cells = drawn(array, "cells", 0);
  ASSERT_NE(cells, nullptr);
  EXPECT_EQ(cells->type, Marker::CUBE_LIST);
  ASSERT_FALSE(cells->points.empty());
  EXPECT_LE(cells->points.size(), 1200u);
  ASSERT_EQ(cells->colors.size(), cells->points.size());
  const auto same = [](const std_msgs::ColorRGBA& a, const std_msgs::ColorRGBA& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
  };
  std::size_t near_side = 0;
  for (std::size_t i = 0; i < cells->points.size(); ++i) {
    const bool near = cells->points[i].x <= 1.0;
    near_side += near ? 1 : 0;
    // The two blocks in two colours, by the side of the split.
    EXPECT_EQ(same(cells->colors[i], cells->colors[0]), near == (cells->points[0].x <= 1.0));
  }

  const Marker* current = drawn(array, "current_cell", 0);
  ASSERT_NE(current, nullptr);
  EXPECT_EQ(current->type, Marker::CUBE_LIST);
  EXPECT_EQ(current->points.size(), near_side);
  for (const geometry_msgs::Point& p : current->points)
    EXPECT_LE(p.x, 1.0);
  EXPECT_EQ(drawn(array, "cells", 1), nullptr);  // the abstraction ignores human 2
}

}  // namespace
}  // namespace oasis::hw::ros_node
