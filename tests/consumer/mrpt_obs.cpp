// travel::mrpt_obs alone: TravelFilter labels a flat patch given as a CObservationPointCloud.
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <travel_mrpt/TravelFilter.hpp>

#include <cstdio>

int main() {
    auto points = mrpt::maps::CSimplePointsMap::Create();
    for (int i = -20; i <= 20; ++i)
        for (int j = -20; j <= 20; ++j) points->insertPoint(0.2f * i + 3.f, 0.2f * j, -1.f);
    mrpt::obs::CObservationPointCloud obs;
    obs.pointcloud = points;
    travel_mrpt::TravelFilterOptions options;
    options.params.sensor_height = 1.0;
    options.params.cluster_objects = false;
    travel_mrpt::TravelFilter filter(options);
    travel_mrpt::TravelFrame frame;
    if (!filter.filter(obs, frame)) return 1;
    const std::size_t ground = frame.result.count(travel::PointClass::Ground);
    std::printf("consumer_mrpt_obs: %zu of %zu points ground\n", ground, frame.cloud.size());
    return ground > frame.cloud.size() / 2 ? 0 : 1;
}
