// travel::mrpt_nav alone: an obstacle source has nothing to hand over before its first frame.
#include <mrpt/maps/CSimplePointsMap.h>
#include <travel_mrpt/TravelObstacleSource.hpp>

#include <cstdio>

int main() {
    travel_mrpt::TravelObstacleSource source;
    mrpt::maps::CSimplePointsMap points;
    mrpt::Clock::time_point stamp{};
    const bool any = source.latest(points, stamp);
    std::printf("consumer_mrpt_nav: source '%s', obstacles before the first frame: %s\n",
                source.name().c_str(), any ? "yes" : "none");
    return any ? 1 : 0;
}
