#pragma once
// A small house built through MeshBuilder (no file reader involved): 10 x 8 m footprint, 5 m
// walls, a gable roof, a window and a door as openings in holes of the front wall, a window on a
// side wall, all at UTM-like coordinates so the local origin matters.
#include "citymodel/mesh_builder.h"
#include "citymodel/taxonomy.h"

namespace cls::test {

inline SemanticMesh toy_house(const Taxonomy& tax) {
  constexpr double X0 = 457800, Y0 = 5439000, Z0 = 110;
  const auto P = [&](double x, double y, double z) { return std::array<double, 3>{X0 + x, Y0 + y, Z0 + z}; };
  MeshBuilder b(tax);
  const int building = b.add_entity(3, tax.find("building"), -1, "house");
  const auto surface = [&](const char* cls, const char* id) { return b.add_entity(2, tax.find(cls), building, id); };
  // Front wall (y = 0) with a window hole and a door hole.
  const Ring window_front{P(2, 0, 2), P(3.2, 0, 2), P(3.2, 0, 3.4), P(2, 0, 3.4), P(2, 0, 2)};
  const Ring door{P(6, 0, 0), P(7, 0, 0), P(7, 0, 2.1), P(6, 0, 2.1), P(6, 0, 0)};
  const int front = surface("wall", "wall-front");
  b.add_polygon({{P(0, 0, 0), P(10, 0, 0), P(10, 0, 5), P(0, 0, 5), P(0, 0, 0)}, window_front, door},
                tax.find("wall"), front, "wall-front-poly");
  b.add_polygon({window_front}, tax.find("window"), b.add_entity(1, tax.find("window"), front, "win-1"), "win-1-poly");
  b.add_polygon({door}, tax.find("door"), b.add_entity(1, tax.find("door"), front, "door-1"), "door-1-poly");
  // Back wall and gable walls; the east gable has a window (on top of the wall, no hole).
  b.add_polygon({{P(0, 8, 0), P(0, 8, 5), P(10, 8, 5), P(10, 8, 0), P(0, 8, 0)}}, tax.find("wall"),
                surface("wall", "wall-back"), "wall-back-poly");
  const int east = surface("wall", "wall-east");
  b.add_polygon({{P(10, 0, 0), P(10, 8, 0), P(10, 8, 5), P(10, 4, 8), P(10, 0, 5), P(10, 0, 0)}}, tax.find("wall"),
                east, "wall-east-poly");
  b.add_polygon({{P(10, 3, 5.5), P(10, 5, 5.5), P(10, 5, 6.6), P(10, 3, 6.6), P(10, 3, 5.5)}}, tax.find("window"),
                b.add_entity(1, tax.find("window"), east, "win-2"), "win-2-poly");
  b.add_polygon({{P(0, 0, 0), P(0, 0, 5), P(0, 4, 8), P(0, 8, 5), P(0, 8, 0), P(0, 0, 0)}}, tax.find("wall"),
                surface("wall", "wall-west"), "wall-west-poly");
  // Roof and ground.
  b.add_polygon({{P(0, 0, 5), P(10, 0, 5), P(10, 4, 8), P(0, 4, 8), P(0, 0, 5)}}, tax.find("roof"),
                surface("roof", "roof-south"), "roof-south-poly");
  b.add_polygon({{P(0, 4, 8), P(10, 4, 8), P(10, 8, 5), P(0, 8, 5), P(0, 4, 8)}}, tax.find("roof"),
                surface("roof", "roof-north"), "roof-north-poly");
  b.add_polygon({{P(0, 0, 0), P(0, 8, 0), P(10, 8, 0), P(10, 0, 0), P(0, 0, 0)}}, tax.find("ground"),
                surface("ground", "ground"), "ground-poly");
  return b.finish();
}

}  // namespace cls::test
