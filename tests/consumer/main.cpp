// Segments a tiny flat patch through the installed library; exits 0 only if it finds ground.
#include <travel/Pipeline.hpp>

#include <cstdio>

int main() {
    travel::Params params;
    params.sensor_height = 1.0;
    travel::PointCloud cloud;
    for (int i = -20; i <= 20; ++i)
        for (int j = -20; j <= 20; ++j) cloud.push_back(0.2f * i + 3.f, 0.2f * j, -1.f);
    travel::Pipeline pipeline(params);
    travel::Result result;
    pipeline.process(cloud, {}, result);
    const std::size_t ground = result.count(travel::PointClass::Ground);
    std::printf("consumer: %zu of %zu points ground\n", ground, cloud.size());
    return ground > cloud.size() / 2 ? 0 : 1;
}
