// travel::mrpt_maps alone: after registerClasses(), MRPT's class registry creates the map layer.
#include <mrpt/rtti/CObject.h>
#include <travel_mrpt/CTraversabilityMap.hpp>
#include <travel_mrpt/Registration.hpp>

#include <cstdio>

int main() {
    travel_mrpt::registerClasses();
    const auto* cls = mrpt::rtti::findRegisteredClass("travel_mrpt::CTraversabilityMap");
    if (cls == nullptr) return 1;
    const auto map = cls->createObject();
    std::printf("consumer_mrpt_maps: created %s\n", map ? cls->className : "nothing");
    return map ? 0 : 1;
}
