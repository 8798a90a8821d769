// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Ready-made test scenes. Each spans about 100 m x 100 m around the origin (the terrain itself
// is unbounded) and expects the sensor at (0, 0), kSensorHeight above the terrain there;
// the road runs along +x.
#pragma once

#include "travel/sim/Scene.hpp"

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace travel::sim {

/// Sensor height above the ground the scenes are designed for (KITTI's HDL-64E) [m].
constexpr double kSensorHeight = 1.73;

/// Level ground at z = 0, nothing else.
Scene flatGround();

/// Flat ground, then a ramp of `slope_deg` from x = 6 m, 15 m long, 20 m wide (|y| <= 10),
/// leading up to a plateau that extends to infinity along +x.
Scene slope(double slope_deg);

/// A road |y| < 4.5 (left) / 5.5 (right) between 0.15 m kerbs topped by raised sidewalks, and a
/// staircase of 3 steps of 0.15 m (0.4 m deep) across the road from x = 8 m up to a landing.
Scene kerbsAndSteps();

/// Gaussian bumps (0.2-0.5 m high, sigma 2-4 m) with 0.02 m sinusoidal roughness everywhere.
Scene bumpyTerrain();

/// Flat ground with three 4.5 x 1.8 x 1.5 m cars (ids 1-3; 1 and 2 side by side 1 m apart),
/// poles (ids 4-6), a 1 m wall (id 7) and a 3 m wall (id 8) partly hidden behind pole 6.
Scene urbanObjects();

/// A 10 deg ramp, a kerb and sidewalk, bumps, a car (id 1), a pole (id 2), a wall (id 3).
Scene mixed();

// ---- Failure scenes of issue 14 (errors seen on unseen SemanticKITTI / off-road scans) ----

/// A road |y| < 5 with, on its left (y = 6), a 1.6 m mesh fence: posts every 2.5 m (ids 1-25)
/// and mesh panels reaching 2 cm above the ground with 0.5 m gaps between them (ids 101-);
/// on its right (y = -7), a 2.5 m wall (id 200) on a 0.3 m high, 0.6 m wide footing (id 201).
/// The bases of fences and walls are what TRAVEL labelled ground 5-20 m away.
Scene fencesAndWalls();

/// Harder fences and walls on rough verges (3-4 cm roughness, 1 m wavelength): on the left,
/// grass rising 0.3 m over 2 m from y = 4 and on its plateau (y = 7), from x = -15 to 15 m, a
/// 1.6 m fence of posts every 2.5 m (ids 1-12) and mesh panels of vertical wires, 8 cm wide
/// every 20 cm, 3 cm above the grass, 70 % of the rays hitting them returned (one id per
/// panel, 101-112: rays pass between the wires); on the right, a bank rising 0.4 m over 3 m
/// from y = -5, and on it (y = -9) a 1.2 m garden wall without footing (id 200, x < 0) and a
/// 2 m wall (id 201, x > 0) on a 0.15 m high, 0.3 m wide footing (id 202).
Scene meshFencesOnRoughVerges();

/// A road |y| < 4 between verges: on the left, grass rising 0.3 m over 2 m (8.5 deg) to a
/// plateau; on the right, an embankment rising 0.5 m over 1.5 m (18 deg) to a plateau; 3 cm
/// roughness (1 m wavelength) everywhere. All of it is ground: what TRAVEL missed 5-40 m away.
Scene grassVerges();

/// Verges with street furniture on them, 0-40 m away: no node of a verge is clear of objects
/// 0.5 m tall (own_plane_clearance). Left: grass rising 0.3 m over 2 m from y = 4, fence posts
/// (0.05 m radius, 1.2 m) every 4 m at y = 6.5; a bank rising 0.2 m over 1 m from y = 14, tree
/// trunks (0.15 m, 5 m) every 8 m at y = 16. Right: an embankment rising 0.5 m over 1.5 m from
/// y = -4, trunks every 8 m at y = -7; a verge rising 0.3 m over 1 m from y = -22, fence posts
/// every 4 m at y = -24. 3 cm roughness (1 m wavelength). Posts and trunks (ids from 1) stand
/// at x = -32..36.
Scene vergesWithStreetFurniture();

/// Uneven meadow: bumps of 0.2-0.6 m (sigma 1.5-4 m), 5 cm roughness (1.2 m wavelength),
/// bushes (0.6-1.2 m boxes, ids 1-8) and tree trunks (0.15-0.3 m radius, ids 11-16). Meant for
/// an OS1-64 about 1.3 m above the ground (kOffRoadSensorHeight).
Scene offRoadMeadow();
constexpr double kOffRoadSensorHeight = 1.3;

// Harsher off-road scenes (grass, puddles, ditches, fences, rocks, slopes) for the OS1-64 1.3 m
// up. Grass (GroundCover) is SemanticKITTI's terrain: ground truth Ground at any height in its
// canopy; bushes and low shrubs are vegetation and rocks objects: NonGround.

/// offRoadMeadow's terrain under grass 0.12 m tall everywhere (half of the rays return from its
/// blades) with patches of 0.3 m (x 4..12, y -10..-2 and -10..-2, -14..-6) and 0.5 m grass (x
/// 9..15, y 2..8; -13..-7, 1..7; 0..6, 11..17); its bushes (ids 1-8, foliage: 70 % of the rays
/// return) and trunks (ids 11-16); low shrubs 0.3-0.5 m high (ids 21-26, 60 %) and rocks
/// 0.2-0.6 m (ids 31-38).
Scene offRoadTallGrassAndRocks();

/// offRoadMeadow's terrain under grass 0.15 m tall everywhere (half of the rays return) and two
/// farm fences: along y = 6 from x = -24 to 24 (wooden posts 0.06 m in radius, 1.3 m, every
/// 3 m: ids 1-17) and along x = 14 from y = -21 to 21 (ids 31-45); between the posts four
/// horizontal wires 1.5 cm thick at 0.2, 0.55, 0.9 and 1.25 m, 60 % of the rays that hit them
/// returned (one id per span: 101- and 201-).
Scene offRoadFenceLines();

/// A dirt track along +x, 3 cm roughness: two ruts 0.1 m deep, 0.35 m wide (|y| 0.6..0.95) with
/// grass 0.1 m between them; puddles in and between the ruts (x = 6, 12, -8, 20, -15; radius
/// 1-1.8 m, 0.1-0.12 m deep, 30 % of the rays mirrored); on the left a ditch 0.6 m deep with
/// 20 deg sides from y = 3.5 (bottom 0.8 m wide), on the right one 0.4 m deep with 15 deg sides
/// from y = -3.5 (bottom 0.6 m); grass 0.2 m tall beyond |y| = 3.2 (ditches included); trunks
/// beyond the left ditch (ids 11-13), bushes beyond the right one (ids 1-3, foliage 70 %).
Scene offRoadTrackWithDitchesRutsAndPuddles();

/// A hillside rising `slope_deg` along +x from x = -40 m for 80 m (the sensor stands on it at
/// x = 0), with offRoadMeadow's bumps and roughness, grass 0.15 m tall everywhere, its bushes
/// (ids 1-8, foliage 70 %) and trunks (ids 11-16), and rocks 0.2-0.6 m (ids 31-38).
Scene offRoadHillside(double slope_deg);

/// Flat ground and one 4.5 x 1.8 x 1.5 m car (id 1) parked beside the sensor along +x, its
/// near side `gap` metres from the sensor (y = gap .. gap + 1.8).
Scene carBesideSensor(double gap);

/// A car that is not a box (4.5 x 1.8 m, 1.48 m high), all parts instance `id`: a body from
/// 0.35 to 0.95 m (bonnet and boot at its top), four tyres, a cabin of six pillars under a roof
/// (1.38-1.48 m) with glass windows - gaps through which rays reach the seats (front seat backs
/// and rear bench up to 1.2 m) or pass on to the far side and beyond. `paint_return` < 1 is a
/// dark paint (body and roof) and `tyre_return` the tyres' share of returned rays.
/// `velocity` [m/s] moves every part during the sweep (see Box::velocity).
std::vector<Box> realisticCar(uint32_t id, const Eigen::Vector2d& centre, double yaw_deg,
                              double paint_return = 1.0, double tyre_return = 1.0,
                              const Eigen::Vector2d& velocity = Eigen::Vector2d::Zero());

/// Flat ground and one realisticCar (id 1, dark paint: 70 % of its body's rays return, 50 % of
/// its tyres') parked along +x beside the sensor, its near side `gap` metres away. What split a
/// real car 2-3 m beside the sensor into six clusters (windows, missing returns).
Scene realisticCarBesideSensor(double gap);

/// The own vehicle, for scenes seen from a car's roof: the part of a KITTI-like car (VW Passat
/// B6 Variant, 4.77 x 1.82 m) that the scanner 1.73 m up sees, its body from 0.35 to 0.95 m
/// (instance kEgoVehicleId) along +x, front 2.7 m ahead of the sensor at (0, 0), tail 2.07 m
/// behind. The lowest beams (-24.9 deg) reach its top beyond 1.7 m: the bonnet and the boot, as
/// on the SemanticKITTI frames (self returns 0.8-1.2 m above the road, 1.3-2.8 m away). Its cabin
/// stays under the beams there (the road is seen all around from 4.1 m): it has none here.
constexpr uint32_t kEgoVehicleId = 900;
std::vector<Box> egoVehicle();

/// realisticCarBesideSensor(gap) seen from the roof of egoVehicle().
Scene realisticCarBesideEgoVehicle(double gap);

/// Flat ground with parked realistic cars at 20-25 m: side on at 21 m on the left (id 1), a
/// dark one beyond it (id 2), end on 24 m behind (id 3). What lost a third of its points.
Scene parkedCarsAt20To25Metres();

/// Flat ground and one realisticCar (id 1) moving at `velocity` [m/s], centred `distance` metres
/// ahead (+x) with yaw `yaw_deg`: it straddles the sweep's start/end azimuth, so the scan sees
/// its two halves 0.1 s apart (what split moving cars at 20-25 m in two).
Scene movingCarAcrossSweepStart(double distance, double yaw_deg, const Eigen::Vector2d& velocity);

// ---- Purity scenes of issue 14 (objects of different instances joined into one cluster) ----

/// A realisticCar (id 1) parked side on along +x, its centre `distance` m to the left (+y), with
/// a person (0.5 x 0.35 x 1.75 m box) `gap` metres beyond its front end (id 2, beside it in
/// azimuth) and another `gap` metres in front of its near side (id 3, between car and sensor).
Scene personBesideCar(double distance, double gap);

/// Four realisticCars (ids 1-4) parked nose to tail along +x, centres `distance` m to the left,
/// `gap` metres between bumpers; a car from x = -12 m on.
Scene parkedCarRow(double distance, double gap);

/// A realisticCar (id 1) parked side on `distance` m to the left, and behind it, `gap` metres
/// beyond its far side, a 20 m long, 1 m thick hedge or wall (id 2) of `height` metres.
Scene carBeforeHedge(double distance, double gap, double height);

/// A realisticCar (id 1) parked side on `distance` m to the left and, `gap` metres beyond its
/// far side, hidden behind it: another realisticCar (id 2, parked alongside) when `behind_is_car`,
/// else a 1.2 m high, 0.5 m wide child or bicycle (id 2, 0.35 m deep) behind its rear window.
/// What is seen of id 2 shows only through id 1's windows.
Scene objectBehindParkedCar(double distance, double gap, bool behind_is_car);

/// Sensor pose in the world: `height` above the terrain at (x, y), attitude
/// R = Rz(yaw) * Ry(pitch) * Rx(roll) (angles in degrees).
Eigen::Isometry3d sensorPoseAt(const Scene& scene, double x, double y, double height,
                               double roll_deg, double pitch_deg, double yaw_deg);

}  // namespace travel::sim
