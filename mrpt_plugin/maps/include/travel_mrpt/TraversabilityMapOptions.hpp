// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// Options of CTraversabilityMap: the map section (travel::MapSection: grid geometry, OctoMap,
// fusion rules; keys, units and documentation in travel/Config.hpp; the grid takes its
// GridGeometry and GridFusionParams parts directly) and the TRAVEL filter
// (TravelFilterOptions: `preset`, every libtravel parameter, the filter keys).
// Read from an ini section; in a CMultiMetricMap .ini both sections of the map,
// [<prefix>_creationOpts] and [<prefix>_insertOpts], accept every key of the map, filter and
// travel sections (a `preset` in either is the base of both; the keys are applied in that
// order: put the geometry in the first and the rest in the second by convention). Each key goes
// through the same rules and messages as in a config file (travel::assignFlatKey); an unknown key
// is an error naming it, the section (file and line when read from a file) and the nearest key.
#pragma once

#include <mrpt/config/CLoadableOptions.h>

#include <string>
#include <vector>

#include "travel/Config.hpp"
#include "travel/traversability/TraversabilityGrid.hpp"
#include "travel_mrpt/TravelFilterOptions.hpp"

namespace travel_mrpt {

// The grid is libtravel's (travel::traversability); MRPT code keeps naming it from here.
using travel::CellState;
using travel::GridFusionParams;
using travel::GridGeometry;
using travel::TraversabilityGrid;

struct TraversabilityMapOptions : public mrpt::config::CLoadableOptions, public travel::MapSection {
    TravelFilterOptions travel;

    travel::MapSection& map() { return *this; }
    const travel::MapSection& map() const { return *this; }

    /// Applies every key of `section` on top of the current values (see the file comment).
    /// Throws travel::ConfigError naming the section and the key.
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                            const std::string& section) override;
    /// The options of a CMultiMetricMap map definition (`prefix`: "<section>_traversabilityMap_NN",
    /// as TSetOfMetricMapInitializers names it): the keys of [<prefix>_creationOpts] and
    /// [<prefix>_insertOpts] read as one section (a `preset` in either is the base of every key
    /// of both; at most one preset), except the keys MRPT itself reads from _creationOpts for
    /// every map (mrpt::maps::TMapGenericParams: enableSaveAs3DObject, ...). A section of this
    /// map kind under <section> that CMultiMetricMap never reads (a misspelt name, an index not
    /// below traversabilityMap_count), with keys in it, is an error naming it and the sections
    /// that are read: its keys would otherwise be lost without a word.
    void loadFromMapDefinition(const mrpt::config::CConfigFileBase& source,
                               const std::string& prefix);
    /// Writes TravelFilterOptions' keys, then every map key.
    void saveToConfigFile(mrpt::config::CConfigFileBase& target,
                          const std::string& section) const override;
    /// travel::applyConfigFile: sections travel, filter and map of a YAML or ini file.
    void loadFromFile(const std::string& path);
    /// Throws travel::ConfigError naming the offending key.
    void validate() const;

  private:
    /// The keys of `sections` as one section, less those in `mrpt_keys` (lower case).
    void loadFromSections(const mrpt::config::CConfigFileBase& source,
                          const std::vector<std::string>& sections,
                          const std::vector<std::string>& mrpt_keys);
};

}  // namespace travel_mrpt
