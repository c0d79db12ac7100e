// The 12 sea creatures of the paper's Fig. 8 (C01..C12), as parts (CreatureParts.h).
#include "CreatureParts.h"

namespace pm::sim::catalog {

namespace {

// ---- The 12 creatures. Coordinates in mm near their final size: x right, y down. ----

Creature seahorse()
{
  const Hsv3 body{48, 0.85, 0.9}, ring{32, 0.85, 0.62}, dark{25, 0.6, 0.25};
  Creature c{{"C01", "seahorse", 45, 130, 27}, {}, 101};
  auto &P = c.parts;
  P.push_back(ellipse({6, -50}, {11, 8.5}, -12, body, 0.85));
  P.push_back(capsule({12, -52}, {30, -47}, 3.8, 3.0, body, 0.55));
  P.push_back(ellipse({1, -61}, {5, 5}, 0, ring, 0.8));
  P.push_back(stripes(capsule({3, -43}, {-3, -24}, 8, 9.5, body, 0.9), ring, 7, 90, 0.25));
  P.push_back(stripes(ellipse({0, -4}, {12.5, 22}, 8, body, 1.0), ring, 7, 90, 0.25));
  P.push_back(polygon({{-11, -16}, {-20, -4}, {-11, 8}}, {40, 0.6, 0.95}, 0.35));
  std::vector<Part> tail;
  chain(tail, {{-2, 14}, {2, 33}, {-1, 48}, {-9, 58}, {-17, 53}, {-14, 45}}, 8, 2.5, body, 0.8);
  for (auto &t : tail)
    P.push_back(stripes(t, ring, 6, 80, 0.3));
  P.push_back(bump(ellipse({9, -52}, {2.4, 2.4}, 0, dark, 0.08)));
  return c;
}

Creature coelacanth()
{
  const Hsv3 body{30, 0.6, 0.5}, spot{45, 0.35, 0.9}, fin{24, 0.55, 0.42};
  Creature c{{"C02", "coelacanth", 145, 70, 60}, {}, 202};
  auto &P = c.parts;
  P.push_back(spots(ellipse({0, 0}, {55, 24}, 0, body, 1.0), spot, 9, 0.45));
  P.push_back(spots(ellipse({-50, 2}, {21, 18}, 0, body, 0.9), spot, 9, 0.4));
  P.push_back(polygon({{48, 0}, {72, -24}, {66, 0}, {72, 24}}, fin, 0.35));
  P.push_back(capsule({50, 0}, {75, 0}, 6, 4, fin, 0.4));
  for (const auto &f : std::vector<std::pair<Vec2, Vec2>>{{{-25, 15}, {-31, 34}}, {{10, 18}, {7, 35}},
                                                          {{5, -20}, {12, -34}}, {{30, -17}, {38, -29}},
                                                          {{32, 15}, {40, 28}}})
    P.push_back(capsule(f.first, f.second, 6, 4, fin, 0.35));
  P.push_back(bump(ellipse({-58, -4}, {3.5, 3.5}, 0, {40, 0.5, 0.15}, 0.06)));
  return c;
}

Creature morayEel()
{
  const Hsv3 body{95, 0.7, 0.55}, spot{85, 0.8, 0.28};
  Creature c{{"C03", "moray eel", 142, 30, 23}, {}, 303};
  auto &P = c.parts;
  std::vector<Vec2> spine;
  for (int i = 0; i <= 12; ++i) {
    const double x = -60 + 11 * i;
    spine.push_back({x, 6 * std::sin(x / 18.0)});
  }
  std::vector<Part> b;
  chain(b, spine, 9, 3, body, 1.0);
  for (auto &p : b)
    P.push_back(spots(p, spot, 6, 0.45));
  P.push_back(spots(ellipse({-62, -1}, {12, 9}, -5, body, 0.95), spot, 6, 0.4));
  P.push_back(capsule({-73, 3}, {-60, 5}, 3, 3, {90, 0.6, 0.45}, 0.5));
  P.push_back(bump(ellipse({-66, -4}, {2.2, 2.2}, 0, {55, 0.8, 0.9}, 0.1)));
  return c;
}

Creature dolphin()
{
  const Hsv3 body{340, 0.45, 0.85}, fin{335, 0.5, 0.7};
  Creature c{{"C04", "dolphin", 80, 60, 45}, {}, 404};
  auto &P = c.parts;
  chain(P, {{30, 24}, {16, 6}, {-4, -9}, {-24, -11}}, 4, 11, body, 1.0);
  P.push_back(capsule({-24, -11}, {-41, -4}, 10, 3.5, body, 0.8));
  P.push_back(polygon({{-3, -17}, {6, -31}, {11, -13}}, fin, 0.4));
  P.push_back(capsule({-12, 1}, {-19, 14}, 4.5, 2, fin, 0.4));
  P.push_back(polygon({{29, 23}, {19, 37}, {34, 29}, {46, 33}}, fin, 0.35));
  P.push_back(bump(ellipse({-29, -13}, {2.2, 2.2}, 0, {330, 0.4, 0.2}, 0.08)));
  return c;
}

Creature squid()
{
  const Hsv3 mantle{22, 0.6, 0.75}, fins{26, 0.4, 0.85}, spot{12, 0.7, 0.5}, arm{18, 0.55, 0.7};
  Creature c{{"C05", "bigfin reef squid", 210, 82.5, 45}, {}, 505};
  auto &P = c.parts;
  P.push_back(spots(ellipse({35, 0}, {64, 39}, 0, fins, 0.25, 0.6), spot, 10, 0.3));
  P.push_back(spots(ellipse({30, 0}, {60, 20}, 0, mantle, 1.0), spot, 7, 0.45));
  P.push_back(ellipse({-38, 0}, {15, 14}, 0, mantle, 0.8));
  for (int k = 0; k < 8; ++k) {
    const double y = -10.5 + 3 * k, yEnd = -26 + 7.5 * k;
    chain(P, {{-48, y}, {-70, y * 1.5}, {-92, yEnd}}, 4, 1.5, arm, 0.3);
  }
  chain(P, {{-48, -2}, {-80, -8}, {-112, -4}}, 2.5, 3, arm, 0.25);
  chain(P, {{-48, 2}, {-80, 8}, {-112, 4}}, 2.5, 3, arm, 0.25);
  for (double s : {-1.0, 1.0})
    P.push_back(bump(ellipse({-38, 9 * s}, {4, 3.5}, 0, {30, 0.5, 0.2}, 0.1)));
  return c;
}

Creature jellyfish()
{
  const Hsv3 bell{310, 0.5, 0.85}, arm{320, 0.6, 0.7}, spot{300, 0.25, 0.95};
  Creature c{{"C06", "jellyfish", 90, 90, 110}, {}, 606};
  auto &P = c.parts;
  P.push_back(spots(ellipse({0, -15}, {42, 30}, 0, bell, 1.0), spot, 8, 0.35));
  for (double x : {-12.0, 0.0, 12.0})
    chain(P, {{x, 8}, {x * 1.3 + 4, 26}, {x * 1.6, 44}}, 6, 3, arm, 0.35);
  for (int k = 0; k < 6; ++k) {
    const double x = -35 + 14 * k;
    chain(P, {{x, 8}, {x + 4, 24}, {x - 2, 38}, {x + 3, 48}}, 2, 1, arm, 0.15);
  }
  return c;
}

Creature turtle()
{
  const Hsv3 shell{70, 0.4, 0.42}, ridge{60, 0.5, 0.25}, skin{65, 0.3, 0.5}, spot{60, 0.15, 0.85};
  Creature c{{"C07", "leatherback sea turtle", 105, 132, 30}, {}, 707};
  auto &P = c.parts;
  P.push_back(stripes(ellipse({0, 5}, {38, 52}, 0, shell, 1.0), ridge, 12, 0, 0.18));
  P.push_back(spots(ellipse({0, -55}, {13, 14}, 0, skin, 0.6), spot, 6, 0.3));
  for (double s : {-1.0, 1.0}) {
    P.push_back(spots(capsule({s * 28, -25}, {s * 54, -4}, 10, 5, skin, 0.3), spot, 6, 0.3));
    P.push_back(ellipse({s * 22, 55}, {10, 14}, s * 30, skin, 0.3));
  }
  P.push_back(capsule({0, 55}, {0, 66}, 5, 2, skin, 0.3));
  return c;
}

Creature octopus()
{
  const Hsv3 body{2, 0.8, 0.7}, sucker{15, 0.35, 0.95};
  Creature c{{"C08", "octopus", 143, 125, 35}, {}, 808};
  auto &P = c.parts;
  P.push_back(spots(ellipse({0, -35}, {28, 32}, 0, body, 1.0), sucker, 7, 0.25));
  P.push_back(ellipse({0, -5}, {22, 16}, 0, body, 0.8));
  for (int k = 0; k < 8; ++k) {
    const double a = (200.0 + 20.0 * k) * M_PI / 180.0, curl = (k % 2 ? 1.0 : -1.0) * 0.5;
    std::vector<Vec2> pts;
    for (int i = 0; i <= 5; ++i) {
      const double rr = 8 + 13 * i, aa = a + curl * i * 0.12;
      pts.push_back({rr * std::cos(aa) * 1.1, 5 - rr * std::sin(aa)});
    }
    std::vector<Part> arm;
    chain(arm, pts, 8, 2, body, 0.35);
    for (auto &p : arm)
      P.push_back(spots(p, sucker, 5, 0.3));
  }
  for (double s : {-1.0, 1.0})
    P.push_back(bump(ellipse({12 * s, -8}, {4, 3.5}, 0, {50, 0.4, 0.9}, 0.1)));
  return c;
}

Creature anemonefish()
{
  const Hsv3 body{25, 0.9, 0.95}, white{30, 0.05, 0.97}, fin{22, 0.9, 0.85};
  Creature c{{"C09", "anemonefish", 120, 36, 50}, {}, 909};
  auto &P = c.parts;
  P.push_back(ellipse({0, 0}, {45, 16}, 0, body, 1.0));
  P.push_back(ellipse({-40, 1}, {14, 13}, 0, body, 0.9));
  P.push_back(polygon({{42, 0}, {60, -16}, {55, 0}, {60, 16}}, fin, 0.3));
  P.push_back(capsule({-10, -14}, {25, -15}, 4, 3, fin, 0.3));
  P.push_back(bump(capsule({-33, -13}, {-33, 13}, 4, 4, white, 0.04)));
  P.push_back(bump(capsule({0, -15}, {0, 15}, 4.5, 4.5, white, 0.04)));
  P.push_back(bump(capsule({38, -9}, {38, 9}, 3, 3, white, 0.04)));
  P.push_back(bump(ellipse({-45, -3}, {2.5, 2.5}, 0, {20, 0.5, 0.15}, 0.05)));
  return c;
}

Creature mobula()
{
  const Hsv3 body{265, 0.45, 0.55}, wing{270, 0.4, 0.5}, tip{275, 0.35, 0.35};
  Creature c{{"C10", "mobula", 100, 80, 20}, {}, 1010};
  auto &P = c.parts;
  P.push_back(ellipse({0, 0}, {18, 22}, 0, body, 1.0));
  for (double s : {-1.0, 1.0}) {
    P.push_back(spots(polygon({{5 * s, -15}, {50 * s, 5}, {8 * s, 18}}, wing, 0.5, 0.8), tip, 9, 0.3));
    P.push_back(capsule({8 * s, -20}, {10 * s, -32}, 3, 2.5, tip, 0.4));
  }
  P.push_back(capsule({0, 20}, {0, 48}, 2.5, 1, tip, 0.3));
  return c;
}

Creature ribbontailRay()
{
  const Hsv3 disc{40, 0.55, 0.7}, blue{205, 0.8, 0.9};
  Creature c{{"C11", "bluespotted ribbontail ray", 85, 150, 15}, {}, 1111};
  auto &P = c.parts;
  P.push_back(spots(ellipse({0, -25}, {42, 48}, 0, disc, 1.0), blue, 9, 0.35));
  P.push_back(stripes(capsule({0, 20}, {0, 100}, 6, 1.5, disc, 0.4), blue, 10, 90, 0.2));
  for (double s : {-1.0, 1.0})
    P.push_back(bump(ellipse({10 * s, -40}, {3, 3}, 0, {35, 0.5, 0.2}, 0.15)));
  return c;
}

Creature crab()
{
  const Hsv3 shell{8, 0.85, 0.8}, claw{12, 0.85, 0.75}, leg{16, 0.75, 0.7}, spot{20, 0.3, 0.92};
  Creature c{{"C12", "crab", 175, 140, 40}, {}, 1212};
  auto &P = c.parts;
  P.push_back(spots(ellipse({0, 10}, {55, 42}, 0, shell, 1.0), spot, 9, 0.25));
  for (double s : {-1.0, 1.0}) {
    P.push_back(capsule({s * 15, -26}, {s * 16, -36}, 3, 3, shell, 0.9));
    P.push_back(capsule({s * 45, -12}, {s * 64, -42}, 9, 8, claw, 0.6));
    P.push_back(ellipse({s * 72, -56}, {20, 13}, s * 55, claw, 0.75));
    P.push_back(capsule({s * 78, -70}, {s * 66, -82}, 5, 3, claw, 0.55));
    for (int k = 0; k < 3; ++k) {
      const double y = 5 + 14 * k;
      chain(P, {{s * 50, y}, {s * 82, y + 12}, {s * 86, y + 32}}, 5, 2.5, leg, 0.35);
    }
  }
  for (double s : {-1.0, 1.0})
    P.push_back(bump(ellipse({s * 16, -37}, {3.5, 3.5}, 0, {0, 0.6, 0.22}, 0.05)));
  return c;
}

} // namespace

const std::vector<std::function<Creature()>> &creatureBuilders()
{
  static const std::vector<std::function<Creature()>> b = {seahorse, coelacanth, morayEel, dolphin, squid, jellyfish,
                                                           turtle, octopus, anemonefish, mobula, ribbontailRay, crab};
  return b;
}

} // namespace pm::sim::catalog
