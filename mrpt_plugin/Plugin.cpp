// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// libtravel_mrpt_plugin.so: a module for MRPT apps that registers travel_mrpt's classes when it
// is loaded (rawlog-edit -p <abs path>, RawLogViewer -l <abs path>, or
// mrpt::system::loadPluginModules()). travel_mrpt and libtravel are linked in statically.
#include <mrpt/core/initializer.h>

#include "travel_mrpt/Registration.hpp"

MRPT_INITIALIZER(travel_mrpt_plugin) {
    travel_mrpt::registerClasses();
}
