// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel.Params: one Python property per parameter, generated from the library's one parameter
// list (TRAVEL_PARAM_LIST through visitFields): name, documentation, unit and range come from
// there, and every assignment goes through travel::assignKey, the rule every loader uses (YAML,
// ini, --set), so a value is accepted or refused with the same message as in a file.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <type_traits>
#include <vector>

#include "Bindings.hpp"
#include "travel/ConfigFields.hpp"
#include "travel/Errors.hpp"
#include "travel/ParamsIO.hpp"

namespace py = pybind11;

namespace travel::python {
namespace {

/// The value of parameter `key` as a Python object (AutoReal: its number).
py::object getParam(const Params& params, const std::string& key) {
    py::object out;
    visitFields(params, [&](const char* name, const auto& value, auto&&...) {
        if (key != name) return;
        using T = fields::Bare<decltype(value)>;
        if constexpr (std::is_same_v<T, AutoReal>)
            out = py::float_(value.value);
        else
            out = py::cast(value);
    });
    if (!out)
        throw ConfigError("unknown parameter '" + key + "'" +
                          fields::didYouMean(key, keyNames<Params>()));
    return out;
}

/// A Python bool, or a numpy one (what `array.any()` returns; numpy is loaded with the module).
bool isBool(py::handle value) {
    return PyBool_Check(value.ptr()) ||
           py::isinstance(value, py::module_::import("numpy").attr("bool_"));
}

/// `value` as the text travel::assignKey parses: the Python type must fit the parameter's
/// (numbers for numbers, bool for bool (numpy's too), str for choices; AutoReal also takes "auto"
/// or "auto(1.2)"); floats are written with the shortest text that reads back exactly.
template <class T>
std::string valueText(const std::string& key, py::handle value) {
    const bool is_bool = isBool(value);
    const bool is_str = PyUnicode_Check(value.ptr());
    auto refuse = [&](const char* expected) {
        return ConfigError("invalid value for '" + key + "': expected " + expected + ", got " +
                           std::string(py::str(py::type::of(value).attr("__name__"))));
    };
    if constexpr (std::is_same_v<T, bool>) {
        if (!is_bool) throw refuse("a bool");
        return py::bool_(py::reinterpret_borrow<py::object>(value)) ? "true" : "false";
    } else if constexpr (std::is_same_v<T, std::string>) {
        if (!is_str) throw refuse("a str");
        return value.cast<std::string>();
    } else if constexpr (std::is_same_v<T, int>) {
        if (is_bool || !PyIndex_Check(value.ptr())) throw refuse("an int");
        return std::string(py::str(py::int_(py::reinterpret_borrow<py::object>(value))));
    } else {
        if (std::is_same_v<T, AutoReal> && is_str) return value.cast<std::string>();
        if (is_bool || is_str || !PyNumber_Check(value.ptr()))
            throw refuse(std::is_same_v<T, AutoReal> ? "a number or 'auto'" : "a number");
        try {
            return fields::format(
                py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>());
        } catch (py::error_already_set& e) {  // an int beyond the double range (10**400)
            if (!e.matches(PyExc_OverflowError)) throw;
            throw ConfigError("invalid value for '" + key +
                              "': " + std::string(py::str(py::type::of(value).attr("__name__"))) +
                              " too large for a float");
        }
    }
}

/// Sets parameter `key` through travel::assignKey (range and choice checks, library messages).
void setParam(Params& params, const std::string& key, py::handle value) {
    std::string text;
    bool found = false;
    visitFields(params, [&](const char* name, const auto& current, auto&&...) {
        if (key != name) return;
        found = true;
        text = valueText<fields::Bare<decltype(current)>>(key, value);
    });
    if (!found || !assignKey(params, key, text))
        throw ConfigError("unknown parameter '" + key + "'" +
                          fields::didYouMean(key, keyNames<Params>()));
}

/// "[unit] description (range [lo, hi])", as in the YAML dump and docs/parameters.md.
template <class T>
std::string propertyDoc(const char* unit, double lo, double hi, const char* description) {
    if constexpr (std::is_same_v<T, std::string>)
        return std::string(description) + " (one of " + unit + ")";
    else if constexpr (std::is_same_v<T, bool>)
        return std::string(description) + " (bool)";
    std::string doc = "[" + std::string(*unit ? unit : "-") + "] " + description + " (" +
                      (std::is_same_v<T, int> ? "int" : "float") + " in " +
                      fields::rangeText(lo, hi, "") + ")";
    if constexpr (std::is_same_v<T, AutoReal>)
        doc +=
            ". Also 'auto' (estimated from the first frames; the number read back is the "
            "fallback until then) or 'auto(1.2)' (auto with that fallback); see is_auto()";
    return doc;
}

bool isAuto(const Params& params, const std::string& key) {
    bool automatic = false, found = false;
    visitFields(params, [&](const char* name, const auto& value, auto&&...) {
        if (key != name) return;
        found = true;
        if constexpr (std::is_same_v<fields::Bare<decltype(value)>, AutoReal>)
            automatic = value.isAuto();
    });
    if (!found) throw ConfigError("unknown parameter '" + key + "'");
    return automatic;
}

Params fromYaml(const std::string& text, const std::string& source) {
    Params params;
    applyParamsText(text, source, params);
    params.validate();
    return params;
}

}  // namespace

void bindParams(py::module_& m) {
    py::register_exception<ConfigError>(m, "ConfigError", PyExc_ValueError);
    py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

    py::class_<Params> params(m, "Params", R"doc(
The parameters of the ground segmentation and object clustering: the `travel` section of the
library's configuration (docs/parameters.md). Defaults: the library's, tuned for the Velodyne
HDL-64E on KITTI; travel-kitti starts from Params.from_preset("hdl64") instead (it adds the car's
self box and min_range 1 m), so use that preset for its labels.

Every parameter is an attribute, documented with its unit and range. Assigning checks the type
and the range at once (the library's rules, the same messages as in a configuration file) and
raises ConfigError (a ValueError) without changing anything on failure. Rules between
parameters (e.g. min_range < max_range) are checked by validate() and by Pipeline(params).

    Params(**kwargs)            defaults, then the given attributes
    Params.from_preset("vlp16") a sensor preset (share/presets)
    Params.from_file(path)      defaults plus a YAML or ini configuration file
)doc");
    params.def(py::init([](const py::kwargs& kwargs) {
                   Params p;
                   for (const auto& [key, value] : kwargs) setParam(p, py::str(key), value);
                   return p;
               }),
               "The library's defaults (not the preset hdl64 travel-kitti starts from), then the "
               "keyword arguments as attributes.");
    visitFields(Params{}, [&](const char* name, const auto& value, const char* unit, double lo,
                              double hi, const char* description) {
        using T = fields::Bare<decltype(value)>;
        const std::string key = name;
        params.def_property(
            name, [key](const Params& p) { return getParam(p, key); },
            [key](Params& p, py::handle v) { setParam(p, key, v); },
            propertyDoc<T>(unit, lo, hi, description).c_str());
    });
    params
        .def_static(
            "from_preset", &loadPreset, py::arg("name"),
            "Defaults plus share/presets/NAME.yaml, validated (see Params.presets()). Raises "
            "ConfigError listing the available presets when there is none of that name.")
        .def_static(
            "from_file",
            [](const py::object& path) {
                Params p;
                applyParamsFile(py::str(py::module_::import("os").attr("fsdecode")(path)), p);
                return p;
            },
            py::arg("path"),
            "Defaults plus a configuration file (YAML or ini; keys at the root or under "
            "`travel:`; `preset: NAME` first starts from a preset), validated. Other sections "
            "are checked and ignored. Errors name the file, line and key (ConfigError).")
        .def_static("from_yaml", &fromYaml, py::arg("text"), py::arg("source") = "<text>",
                    "As from_file, on a text; `source` names it in messages.")
        .def_static("presets", &availablePresets, "Names of the available sensor presets.")
        .def_static("keys", &keyNames<Params>, "Every parameter name, in declaration order.")
        .def("to_yaml", &paramsToYaml,
             "Every parameter as `key: value` after its documentation; from_yaml() reads it "
             "back identically.")
        .def("validate", &Params::validate,
             "Checks every range and the rules between parameters; raises ConfigError naming "
             "the first offending parameter.")
        .def("is_auto", &isAuto, py::arg("name"),
             "True when the parameter is set to 'auto' (sensor_height, mount_roll_deg, "
             "mount_pitch_deg).")
        .def(
            "to_dict",
            [](const Params& p) {
                py::dict d;
                for (const std::string& key : keyNames<Params>()) d[key.c_str()] = getParam(p, key);
                return d;
            },
            "Every parameter as {name: value} (AutoReal: its number; see is_auto()).")
        // An operator: with anything but Params, NotImplemented (so == is False), not TypeError.
        .def(
            "__eq__",
            [](const Params& a, const Params& b) { return paramsToYaml(a) == paramsToYaml(b); },
            py::is_operator())
        .def("__copy__", [](const Params& p) { return Params(p); })
        .def("__deepcopy__", [](const Params& p, const py::dict&) { return Params(p); })
        .def(
            "__repr__",
            [](const Params& p) {
                std::string text = "travel.Params(";
                const Params defaults;
                const std::string sep = ", ";
                bool first = true;
                for (const std::string& key : keyNames<Params>()) {
                    const py::object v = getParam(p, key);
                    if (v.equal(getParam(defaults, key)) && isAuto(p, key) == isAuto(defaults, key))
                        continue;
                    text += (first ? "" : sep) + key + "=" +
                            (isAuto(p, key) ? "'auto(" + std::string(py::str(v)) + ")'"
                                            : std::string(py::repr(v)));
                    first = false;
                }
                return text + ")";
            })
        // Unpickling restores the values as they were, not validated: a Params may exist before
        // validate() passes (the rules between parameters), and pickle must not refuse it.
        .def(py::pickle([](const Params& p) { return paramsToYaml(p); },
                        [](const std::string& yaml) {
                            Params p;
                            applyParamsText(yaml, "<pickle>", p);
                            return p;
                        }));
}

}  // namespace travel::python
