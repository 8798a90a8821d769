// Reads parameters through the installed travel::config (yaml-cpp linked through it) and refuses
// an unknown key; exits 0 only if both behave.
#include <travel/Errors.hpp>
#include <travel/ParamsIO.hpp>

#include <cstdio>

int main() {
    travel::Params params;
    travel::applyParamsText("travel:\n  sensor_height: 1.0\n  tgf_resolution: 2\n", "consumer",
                            params);
    params.validate();
    if (params.tgf_resolution != 2.0 || params.sensor_height != 1.0) return 1;
    try {
        travel::applyParamsText("sensor_hieght: 1.0\n", "consumer", params);
    } catch (const travel::ConfigError& e) {
        std::printf("consumer_config: %s\n", e.what());
        return 0;
    }
    return 1;
}
