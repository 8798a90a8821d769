// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Options of travel_mrpt::TravelFilter: the ground segmentation (travel::Params, section
// `travel`) and the filter's own keys (travel::FilterSection, section `filter`, declared with
// their documentation in travel/Config.hpp). Loaded by the one loader (travel/ConfigIO.hpp) from
// a file or a YAML map, or from a flat ini section (CLoadableOptions: CMultiMetricMap .ini files),
// where `preset` comes first and every other key goes through the same per-key rules and
// messages. Errors are travel::ConfigError (a std::runtime_error).
#pragma once

#include <mrpt/config/CLoadableOptions.h>

#include <string>

#include "travel/Config.hpp"
#include "travel/Params.hpp"

namespace mrpt::containers {
class yaml;
}

namespace travel_mrpt {

using travel::toString;
using travel::VelocitySource;
using travel::velocitySourceFromString;

struct TravelFilterOptions : public mrpt::config::CLoadableOptions, public travel::FilterSection {
    travel::Params params;  ///< libtravel parameters (deskew is params.deskew)
    /// The tracker's parameters (section `tracking`), used when track_objects is set.
    travel::TrackingParams tracking;

    /// The sections the filter takes from a whole configuration (travel, filter, tracking), and
    /// back: the one place that knows which they are.
    void fromConfig(const travel::Config& config);
    void toConfig(travel::Config& config) const;

    /// Flat ini section: `preset`, then filter and tracking keys and libtravel parameters (same
    /// names).
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                            const std::string& section) override;
    /// Writes every key (libtravel parameters then filter keys), doubles exactly.
    void saveToConfigFile(mrpt::config::CConfigFileBase& target,
                          const std::string& section) const override;

    /// A YAML map with the sections `travel:` and `filter:` (keys at the root: travel's), read
    /// by travel::applyConfigText; other sections are checked and ignored.
    void loadFromYaml(const mrpt::containers::yaml& cfg);
    /// travel::applyConfigFile (YAML or ini with sections [travel], [filter]).
    void loadFromFile(const std::string& path);

    /// The filter section's rules (bad regex, max_motion_age <= 0...) and the tracking one's.
    void validate() const {
        travel::FilterSection::validate();
        tracking.validate();
    }
};

}  // namespace travel_mrpt
