// Copyright (c) 2026, The TRAVEL for MRPT developers. BSD-3-Clause.
//
// travel.Pipeline and what goes in and out of it: numpy points in (checked here, copied once
// into the library's structure-of-arrays cloud, without the GIL), labels and cluster ids out
// (the library's vectors handed to numpy, no copy), clusters and the terrain model as arrays;
// the scan reader, the .label writer and the metrics, all the library's.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "Bindings.hpp"
#include "travel/Errors.hpp"
#include "travel/Pipeline.hpp"
#include "travel/Preprocessing.hpp"
#include "travel/eval/KittiIO.hpp"
#include "travel/eval/Metrics.hpp"
#include "travel/eval/ObjectMetrics.hpp"
#include "travel/io/ScanIO.hpp"

namespace py = pybind11;

namespace travel::python {
namespace {

// ---- Arrays --------------------------------------------------------------------------------

/// Hands `values` to numpy without copying: the array owns the vector from now on.
template <class T, class V>
py::array_t<T> adopt(std::vector<V>&& values, std::vector<py::ssize_t> shape) {
    static_assert(sizeof(T) == sizeof(V), "element types must have the same layout");
    auto* owned = new std::vector<V>(std::move(values));
    py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<V>*>(p); });
    return py::array_t<T>(shape, reinterpret_cast<const T*>(owned->data()), owner);
}

/// An (items.size(), C) array of get(item)[c] (or (items.size(),) for C == 1).
template <class T, int C, class Item, class Get>
py::array_t<T> columns(const std::vector<Item>& items, Get get) {
    using Stored = std::conditional_t<std::is_same_v<T, bool>, uint8_t, T>;  // not vector<bool>
    std::vector<Stored> out;
    out.reserve(items.size() * C);
    for (const Item& item : items) {
        if constexpr (C == 1) {
            out.push_back(static_cast<Stored>(get(item)));
        } else {
            const auto v = get(item);
            for (int c = 0; c < C; ++c) out.push_back(static_cast<Stored>(v[c]));
        }
    }
    const auto n = static_cast<py::ssize_t>(items.size());
    return adopt<T>(std::move(out),
                    C == 1 ? std::vector<py::ssize_t>{n} : std::vector<py::ssize_t>{n, C});
}

char dtypeKind(const py::array& a) {
    return a.dtype().kind();
}

/// "(3,)", "(3, 4)"; a negative size (any) is "N".
std::string shapeText(const std::vector<py::ssize_t>& shape) {
    std::string text = "(";
    for (std::size_t k = 0; k < shape.size(); ++k)
        text += (k ? ", " : "") + (shape[k] < 0 ? std::string("N") : std::to_string(shape[k]));
    return text + (shape.size() == 1 ? ",)" : ")");
}

std::vector<py::ssize_t> shapeOf(const py::array& a) {
    return {a.shape(), a.shape() + a.ndim()};
}

/// An (N,) array-like as a std::vector<T>, or ValueError naming `what`: a wrong shape, a dtype
/// whose kind is not in `kinds`, or, for an integer T, a value outside [lo, hi] (T's range by
/// default): integers are converted only when they fit, never wrapped (257 is not class 1).
template <class T>
std::vector<T> vectorFrom(py::handle object, py::ssize_t n, const char* what, const char* kinds,
                          std::optional<int64_t> lo_bound = std::nullopt,
                          std::optional<int64_t> hi_bound = std::nullopt) {
    const py::array a = py::array::ensure(object);
    if (!a) throw py::value_error(std::string(what) + ": expected an array");
    if (a.ndim() != 1 || (n >= 0 && a.shape(0) != n))
        throw py::value_error(std::string(what) + ": expected shape " + shapeText({n}) + ", got " +
                              shapeText(shapeOf(a)));
    const char kind = dtypeKind(a);
    if (!std::string(kinds).empty() && std::string(kinds).find(kind) == std::string::npos)
        throw py::value_error(std::string(what) + ": dtype " + std::string(py::str(a.dtype())) +
                              " is not accepted (kinds '" + kinds + "')");
    if constexpr (std::is_integral_v<T>) {
        // T's range only here: converting a float type's range to int64_t is undefined.
        const int64_t lo =
            lo_bound.value_or(static_cast<int64_t>(std::numeric_limits<T>::lowest()));
        const int64_t hi = hi_bound.value_or(static_cast<int64_t>(std::numeric_limits<T>::max()));
        if (kind == 'i' || kind == 'u') {  // through 64 bits of the input's signedness
            auto checked = [&](auto typed) {
                std::vector<T> out(static_cast<std::size_t>(typed.size()));
                for (std::size_t i = 0; i < out.size(); ++i) {
                    const auto v = typed.data()[i];
                    const bool fits =
                        kind == 'u'
                            ? static_cast<uint64_t>(v) <= static_cast<uint64_t>(hi) &&
                                  (lo <= 0 || static_cast<uint64_t>(v) >= static_cast<uint64_t>(lo))
                            : static_cast<int64_t>(v) >= lo && static_cast<int64_t>(v) <= hi;
                    if (!fits)
                        throw py::value_error(std::string(what) + ": values must be in [" +
                                              std::to_string(lo) + ", " + std::to_string(hi) +
                                              "], got " + std::to_string(v) + " at index " +
                                              std::to_string(i));
                    out[i] = static_cast<T>(v);
                }
                return out;
            };
            constexpr int flags = py::array::c_style | py::array::forcecast;
            return kind == 'u' ? checked(py::array_t<uint64_t, flags>::ensure(a))
                               : checked(py::array_t<int64_t, flags>::ensure(a));
        }
    }
    const auto typed = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(a);
    return std::vector<T>(typed.data(), typed.data() + typed.size());
}

/// A fixed-size float array-like (attitude, velocity, gravity) as doubles.
std::vector<double> fixedFrom(py::handle object, py::ssize_t size, const char* what) {
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
    if (!a || a.size() != size)
        throw py::value_error(std::string(what) + ": expected " + std::to_string(size) +
                              " numbers");
    std::vector<double> v(a.data(), a.data() + size);
    for (double x : v)
        if (!std::isfinite(x)) throw py::value_error(std::string(what) + ": not finite");
    return v;
}

/// The layout of an (N, 3) or (N, 4) float32 / float64 array: read in place, any strides.
struct PointsView {
    const char* data = nullptr;
    py::ssize_t n = 0, cols = 0, row_stride = 0, col_stride = 0;
    bool is_double = false;
};

/// `object` (a numpy array, or anything numpy reads: a list, ...) as an (N, 3) or (N, 4) float32
/// or float64 array in the machine's byte order, or ValueError naming `what`. An array of that
/// form is returned as is (read in place); one of the other byte order is converted (a copy).
/// The dtype is compared by its type, not by identity: an unpickled array's float32 dtype is an
/// equal but distinct object.
py::array pointsArray(py::handle object, const char* what = "points") {
    py::array a = py::array::ensure(object);
    if (!a) throw py::value_error(std::string(what) + ": expected an (N, 3) or (N, 4) array");
    if (a.ndim() != 2 || (a.shape(1) != 3 && a.shape(1) != 4))
        throw py::value_error(
            std::string(what) +
            ": expected shape (N, 3) or (N, 4) (x, y, z[, intensity]), "
            "got ndim " +
            std::to_string(a.ndim()) +
            (a.ndim() >= 2 ? " with " + std::to_string(a.shape(1)) + " columns" : std::string()));
    const py::dtype dtype = a.dtype();
    const bool f32 = dtype.num() == py::dtype::of<float>().num();
    const bool f64 = dtype.num() == py::dtype::of<double>().num();
    if (!f32 && !f64)
        throw py::value_error(std::string(what) + ": dtype must be float32 or float64, got " +
                              std::string(py::str(py::handle(dtype))));
    if (!dtype.attr("isnative").cast<bool>()) {
        constexpr int flags = py::array::forcecast;
        a = f64 ? py::array(py::array_t<double, flags>::ensure(a))
                : py::array(py::array_t<float, flags>::ensure(a));
    }
    return a;
}

/// The layout of an array checked by pointsArray().
PointsView viewOf(const py::array& a) {
    return {static_cast<const char*>(a.data()),
            a.shape(0),
            a.shape(1),
            a.strides(0),
            a.strides(1),
            a.dtype().num() == py::dtype::of<double>().num()};
}

template <class T, int Cols>
void copyRows(const PointsView& v, float* const out[4]) {
    const auto n = static_cast<std::size_t>(v.n);
    for (std::size_t i = 0; i < n; ++i) {  // one pass over the rows: each is read once
        const char* row = v.data + static_cast<py::ssize_t>(i) * v.row_stride;
        for (int c = 0; c < Cols; ++c)
            out[c][i] = static_cast<float>(*reinterpret_cast<const T*>(row + c * v.col_stride));
        if constexpr (Cols == 3) out[3][i] = 0.f;
    }
}

template <class T, int Cols>
void copyPacked(const T* in, std::size_t n, float* const out[4]) {
    float *x = out[0], *y = out[1], *z = out[2], *intensity = out[3];
    for (std::size_t i = 0; i < n; ++i) {
        const T* row = in + i * Cols;
        x[i] = static_cast<float>(row[0]), y[i] = static_cast<float>(row[1]);
        z[i] = static_cast<float>(row[2]);
        intensity[i] = Cols == 4 ? static_cast<float>(row[Cols - 1]) : 0.f;
    }
}

/// The one copy on the way in: (N, 3|4) rows into the library's x, y, z, intensity vectors
/// (reused, so no allocation once warmed up).
template <class T>
void copyColumns(const PointsView& v, PointCloud& cloud) {
    const auto n = static_cast<std::size_t>(v.n);
    cloud.x.resize(n), cloud.y.resize(n), cloud.z.resize(n), cloud.intensity.resize(n);
    float* const out[4] = {cloud.x.data(), cloud.y.data(), cloud.z.data(), cloud.intensity.data()};
    const bool packed = v.col_stride == sizeof(T) && v.row_stride == v.cols * v.col_stride;
    if (packed && v.cols == 4)  // C-contiguous: strides known at compile time (vectorised)
        copyPacked<T, 4>(static_cast<const T*>(static_cast<const void*>(v.data)), n, out);
    else if (packed)
        copyPacked<T, 3>(static_cast<const T*>(static_cast<const void*>(v.data)), n, out);
    else
        v.cols == 4 ? copyRows<T, 4>(v, out) : copyRows<T, 3>(v, out);
}

// ---- Pickle states --------------------------------------------------------------------------
// Scan, Result, Clusters and Terrain pickle as tuples of what they expose (arrays, numbers,
// text), nested for a Result's clusters and terrain. Not through LabelledFrameCodec: a Result
// holds no points, and the codec's terrain keeps neither the empty nodes nor a node's count,
// weight, search flag and both planes, which Terrain exposes. The ...State() functions return
// the tuple as py::object, the type the ...FromState() readers take (pybind11 wants the same):
// a reader checks the state itself, so that a wrong one gets a message naming the item.

/// Element type and columns of a per-item array: (K,) for C == 1, else (K, C).
template <class T, int C>
struct Column {
    using Type = T;
    using Stored = std::conditional_t<std::is_same_v<T, bool>, uint8_t, T>;  // any byte of a bool
    static constexpr int cols = C;
    static std::vector<py::ssize_t> shape(py::ssize_t rows) {
        return C == 1 ? std::vector<py::ssize_t>{rows} : std::vector<py::ssize_t>{rows, C};
    }
};

/// The inverse of columns(): set(items[i], row i) for an array checked by StateReader::array.
template <class Col, class Item, class Set>
void fromColumns(const py::array& a, std::vector<Item>& items, Set set) {
    const auto* rows = static_cast<const typename Col::Stored*>(a.data());
    for (std::size_t i = 0; i < items.size(); ++i) set(items[i], rows + i * Col::cols);
}

std::string typeName(py::handle object) {
    return py::str(py::type::of(object).attr("__name__"));
}

/// Reads a pickle state, a tuple of `size` items, item by item. Each refusal is a ValueError
/// "cannot unpickle <context>: <item>: <why>": a corrupt or foreign state must not reach the
/// library as sizes or values it never produces.
class StateReader {
  public:
    StateReader(std::string context, py::handle state, std::size_t size)
        : context_(std::move(context)) {
        const std::string expected = "expected a tuple of " + std::to_string(size) + " items";
        if (!py::isinstance<py::tuple>(state))
            throw py::value_error(prefix() + expected + ", got " + typeName(state));
        items_ = py::reinterpret_borrow<py::tuple>(state);
        if (items_.size() != size)
            throw py::value_error(prefix() + expected + ", got " + std::to_string(items_.size()));
    }

    /// The context of item `name` when it holds a state of its own.
    std::string context(const char* name) const { return context_ + ": " + name; }

    py::object next() { return items_[next_++]; }

    [[noreturn]] void fail(const char* name, const std::string& why) const {
        throw py::value_error(prefix() + name + ": " + why);
    }

    double real(const char* name) {
        const py::object item = next();
        if (!PyFloat_Check(item.ptr())) fail(name, "expected a float, got " + typeName(item));
        return item.cast<double>();
    }

    /// A float of the library's (float32): finite and in float's range.
    float real32(const char* name) {
        const double v = real(name);
        if (!(std::abs(v) <= std::numeric_limits<float>::max()))
            fail(name, "expected a finite float32, got " + std::to_string(v));
        return static_cast<float>(v);
    }

    int64_t integer(const char* name, int64_t lo, int64_t hi) {
        const py::object item = next();
        const std::string expected =
            "expected an int in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got ";
        if (!PyLong_Check(item.ptr()) || PyBool_Check(item.ptr()))
            fail(name, expected + typeName(item));
        int overflow = 0;
        const long long v = PyLong_AsLongLongAndOverflow(item.ptr(), &overflow);
        if (overflow || v < lo || v > hi) fail(name, expected + std::string(py::repr(item)));
        return v;
    }

    std::string text(const char* name) {
        const py::object item = next();
        if (!PyUnicode_Check(item.ptr())) fail(name, "expected a str, got " + typeName(item));
        return item.cast<std::string>();
    }

    /// An array of T's dtype (either byte order) and `shape` (a negative size: any), as a
    /// native C-ordered array: the item itself when it is one (no copy).
    template <class T>
    py::array array(const char* name, const std::vector<py::ssize_t>& shape) {
        return checkedArray<T>(name, next(), shape);
    }

    /// As array(), or an empty array for None.
    template <class T>
    py::array arrayOrNone(const char* name, const std::vector<py::ssize_t>& shape) {
        const py::object item = next();
        return item.is_none() ? py::array_t<T>(0) : checkedArray<T>(name, item, shape);
    }

  private:
    std::string prefix() const { return "cannot unpickle " + context_ + ": "; }

    template <class T>
    py::array checkedArray(const char* name, const py::object& item,
                           const std::vector<py::ssize_t>& shape) {
        const py::dtype dtype = py::dtype::of<T>();
        const std::string expected = "expected a " + std::string(py::str(py::handle(dtype))) +
                                     " array of shape " + shapeText(shape);
        if (!py::isinstance<py::array>(item)) fail(name, expected + ", got " + typeName(item));
        const auto a = py::reinterpret_borrow<py::array>(item);
        bool ok = a.dtype().num() == dtype.num() && a.ndim() == py::ssize_t(shape.size());
        for (std::size_t k = 0; ok && k < shape.size(); ++k)
            ok = shape[k] < 0 || a.shape(py::ssize_t(k)) == shape[k];
        if (!ok)
            fail(name, expected + ", got " + std::string(py::str(py::handle(a.dtype()))) +
                           " of shape " + shapeText(shapeOf(a)));
        py::array out = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(a);
        if (!out) fail(name, "cannot convert the array to native byte order");
        // A copy of its own, writable: copy.copy() hands over the original's arrays, and a
        // protocol 5 buffer may be read-only.
        return out.is(a) || !out.writeable() ? py::array(out.attr("copy")()) : out;
    }

    std::string context_;
    py::tuple items_;
    std::size_t next_ = 0;
};

// ---- Scan ----------------------------------------------------------------------------------

/// A scan read by the library's reader, kept in the library's layout so that process() takes
/// it without any copy.
struct ScanPy {
    PointCloud cloud;
    std::string path, format;
};

py::array_t<float> scanPoints(const ScanPy& s) {
    const std::size_t n = s.cloud.size();
    py::array_t<float> out({static_cast<py::ssize_t>(n), py::ssize_t{4}});
    auto w = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < n; ++i) {
        const auto r = static_cast<py::ssize_t>(i);
        w(r, 0) = s.cloud.x[i], w(r, 1) = s.cloud.y[i], w(r, 2) = s.cloud.z[i];
        w(r, 3) = s.cloud.intensity.empty() ? 0.f : s.cloud.intensity[i];
    }
    return out;
}

py::object scanRings(const ScanPy& s) {
    if (!s.cloud.hasRing()) return py::none();
    return py::array_t<uint16_t>(static_cast<py::ssize_t>(s.cloud.size()), s.cloud.ring.data());
}

py::object scanTimes(const ScanPy& s) {
    if (!s.cloud.hasTime()) return py::none();
    return py::array_t<float>(static_cast<py::ssize_t>(s.cloud.size()), s.cloud.time.data());
}

py::object scanState(const ScanPy& s) {
    return py::make_tuple(s.path, s.format, scanPoints(s), scanRings(s), scanTimes(s));
}

ScanPy scanFromState(const py::object& state) {
    StateReader in("travel.Scan", state, 5);
    ScanPy s;
    s.path = in.text("path");
    s.format = in.text("format");
    try {
        if (scanFormatFromString(s.format) == ScanFormat::Auto)
            in.fail("format", "'auto' is no format read");
    } catch (const ConfigError& e) {
        in.fail("format", e.what());
    }
    const py::array points = in.array<float>("points", {-1, 4});
    const py::ssize_t n = points.shape(0);
    copyColumns<float>(viewOf(points), s.cloud);
    const py::array rings = in.arrayOrNone<uint16_t>("rings", {n});
    const py::array times = in.arrayOrNone<float>("times", {n});
    const auto* ring = static_cast<const uint16_t*>(rings.data());
    const auto* time = static_cast<const float*>(times.data());
    s.cloud.ring.assign(ring, ring + rings.size());
    s.cloud.time.assign(time, time + times.size());
    return s;
}

// ---- Result --------------------------------------------------------------------------------

struct ClustersPy {
    py::array ids, num_points, first_point, centroids, aabb_min, aabb_max, obb_center, obb_extent,
        obb_yaw, ground_z, height_above_ground;
    std::size_t size = 0;
};

/// Clusters' arrays, in the order of its pickle state: visit(name, member, doc, Column<T, C>,
/// get(summary) -> row) each.
template <class Visit>
void forEachClusterArray(Visit&& visit) {
    using S = ClusterSummary;
    using P = ClustersPy;
    using U1 = Column<uint32_t, 1>;
    using F1 = Column<float, 1>;
    using F3 = Column<float, 3>;
    visit("ids", &P::ids, "(K,) uint32", U1{}, [](const S& s) { return s.id; });
    visit("num_points", &P::num_points, "(K,) uint32", U1{},
          [](const S& s) { return s.num_points; });
    visit("first_point", &P::first_point,
          "(K,) uint32 smallest input index (ids are ordered by it)", U1{},
          [](const S& s) { return s.first_point; });
    visit("centroids", &P::centroids, "(K, 3) float32", F3{},
          [](const S& s) { return s.centroid; });
    visit("aabb_min", &P::aabb_min, "(K, 3) float32", F3{}, [](const S& s) { return s.aabb_min; });
    visit("aabb_max", &P::aabb_max, "(K, 3) float32", F3{}, [](const S& s) { return s.aabb_max; });
    visit("obb_center", &P::obb_center, "(K, 3) float32", F3{},
          [](const S& s) { return s.obb_center; });
    visit("obb_extent", &P::obb_extent, "(K, 3) float32", F3{},
          [](const S& s) { return s.obb_extent; });
    visit("obb_yaw", &P::obb_yaw, "(K,) float32 [rad]", F1{}, [](const S& s) { return s.obb_yaw; });
    visit("ground_z", &P::ground_z, "(K,) float32 [m], NaN if unknown", F1{},
          [](const S& s) { return s.ground_z; });
    visit("height_above_ground", &P::height_above_ground, "(K,) float32 [m]", F1{},
          [](const S& s) { return s.height_above_ground; });
}

/// How many items visit() is called with, i.e. a state's size.
template <class ForEach>
std::size_t countOf(ForEach for_each) {
    std::size_t n = 0;
    for_each([&n](auto&&...) { ++n; });
    return n;
}

ClustersPy clustersFrom(const std::vector<ClusterSummary>& c) {
    ClustersPy out;
    out.size = c.size();
    forEachClusterArray(
        [&](const char*, py::array ClustersPy::*member, const char*, auto col, auto get) {
            using Col = decltype(col);
            out.*member = columns<typename Col::Type, Col::cols>(c, get);
        });
    return out;
}

py::object clustersState(const ClustersPy& c) {
    py::list items;
    forEachClusterArray(
        [&](const char*, py::array ClustersPy::*member, auto&&...) { items.append(c.*member); });
    return py::tuple(items);
}

ClustersPy clustersFromState(const py::object& state, const std::string& context) {
    StateReader in(context, state, countOf([](auto visit) { forEachClusterArray(visit); }));
    ClustersPy out;
    py::ssize_t k = -1;  // the row count: the first array's
    forEachClusterArray(
        [&](const char* name, py::array ClustersPy::*member, const char*, auto col, auto) {
            using Col = decltype(col);
            out.*member = in.array<typename Col::Type>(name, Col::shape(k));
            k = (out.*member).shape(0);
        });
    out.size = static_cast<std::size_t>(k);
    return out;
}

/// The terrain model of one frame; each per-node array is built on its first read and kept.
struct TerrainPy {
    std::shared_ptr<const TerrainModel> model;
    mutable std::map<int, py::object> arrays;  ///< per-node arrays once read, by slot
};

py::array_t<float> triangleCornersXYZ(const TerrainModel& t) {
    const auto m = static_cast<py::ssize_t>(t.nodes.size());
    std::vector<float> xyz;
    xyz.reserve(t.nodes.size() * 9);
    for (std::size_t i = 0; i < t.nodes.size(); ++i) {
        const auto xy = t.triangleCorners(static_cast<int>(i));
        for (int k = 0; k < 3; ++k) {
            xyz.push_back(xy[static_cast<std::size_t>(k)].x());
            xyz.push_back(xy[static_cast<std::size_t>(k)].y());
            xyz.push_back(t.nodes[i].corner_z[k]);
        }
    }
    return adopt<float>(std::move(xyz), {m, 3, 3});
}

/// Terrain's per-node arrays, in the order of its pickle state: visit(name, doc, Column<T, C>,
/// get(node) -> row, set(node, row)) each. A null doc: in the state only (corners shows it).
template <class Visit>
void forEachNodeArray(Visit&& visit) {
    using N = TriNode;
    using V3 = Eigen::Map<const Eigen::Vector3f>;
    visit(
        "node_class",
        "(M,) uint8: 0 empty, 1 unknown (too few points), 2 terrain, 3 obstacle (too steep)",
        Column<uint8_t, 1>{}, [](const N& n) { return n.node_class; },
        [](N& n, const uint8_t* v) { n.node_class = static_cast<NodeClass>(*v); });
    visit(
        "num_points", "(M,) uint32", Column<uint32_t, 1>{}, [](const N& n) { return n.count; },
        [](N& n, const uint32_t* v) { n.count = *v; });
    visit(
        "planes", "(M, 4) float32 node-wise PCA plane (sx, sy, sz, d): s.p + d = 0",
        Column<float, 4>{},
        [](const N& n) { return Eigen::Vector4f(n.normal.x(), n.normal.y(), n.normal.z(), n.d); },
        [](N& n, const float* v) { n.normal = V3(v), n.d = v[3]; });
    visit(
        "means", "(M, 3) float32 mean of the node's points", Column<float, 3>{},
        [](const N& n) { return n.mean; }, [](N& n, const float* v) { n.mean = V3(v); });
    visit(
        "weights", "(M,) float32 the paper's node weight (eq. 1)", Column<float, 1>{},
        [](const N& n) { return n.weight; }, [](N& n, const float* v) { n.weight = *v; });
    visit(
        "reached", "(M,) bool reached by the traversable graph search", Column<bool, 1>{},
        [](const N& n) { return n.reached; }, [](N& n, const uint8_t* v) { n.reached = *v; });
    visit(
        "traversable",
        "(M,) bool the final decision: the node's points are labelled against ground_planes",
        Column<bool, 1>{}, [](const N& n) { return n.traversable; },
        [](N& n, const uint8_t* v) { n.traversable = *v; });
    visit(
        "ground_planes",
        "(M, 4) float32 TTMF's refitted plane (sx, sy, sz, d); meaningful where traversable",
        Column<float, 4>{},
        [](const N& n) {
            return Eigen::Vector4f(n.refit_normal.x(), n.refit_normal.y(), n.refit_normal.z(),
                                   n.refit_d);
        },
        [](N& n, const float* v) { n.refit_normal = V3(v), n.refit_d = v[3]; });
    visit(
        "corner_z", nullptr, Column<float, 3>{}, [](const N& n) { return n.corner_z; },
        [](N& n, const float* v) { n.corner_z = V3(v); });
}

/// (resolution, cells_per_side, origin_xy, seed_node, num_components, per-node arrays...).
py::object terrainState(const TerrainPy& t) {
    const TerrainModel& model = *t.model;
    py::list items(py::make_tuple(model.resolution, model.cells_per_side, model.origin_xy,
                                  model.seed_node, model.num_components));
    forEachNodeArray([&](const char*, const char*, auto col, auto get, auto) {
        using Col = decltype(col);
        items.append(columns<typename Col::Type, Col::cols>(model.nodes, get));
    });
    return py::tuple(items);
}

TerrainPy terrainFromState(const py::object& state, const std::string& context) {
    StateReader in(context, state, 5 + countOf([](auto visit) { forEachNodeArray(visit); }));
    auto model = std::make_shared<TerrainModel>();
    model->resolution = in.real32("resolution");
    // 4 * side^2 nodes fit an int (TriGridGeometry::numNodes).
    model->cells_per_side = static_cast<int>(in.integer("cells_per_side", 0, 23170));
    model->origin_xy = in.real32("origin_xy");
    const int m = model->numNodes();
    model->seed_node = static_cast<int>(in.integer("seed_node", -1, m - 1));
    model->num_components =
        static_cast<int>(in.integer("num_components", 0, std::numeric_limits<int>::max()));
    std::vector<py::array> arrays;  // all checked before the nodes are allocated
    forEachNodeArray([&](const char* name, const char*, auto col, auto, auto) {
        using Col = decltype(col);
        arrays.push_back(in.array<typename Col::Type>(name, Col::shape(m)));
    });
    model->nodes.resize(static_cast<std::size_t>(m));
    std::size_t k = 0;
    forEachNodeArray([&](const char*, const char*, auto col, auto, auto set) {
        fromColumns<decltype(col)>(arrays[k++], model->nodes, set);
    });
    for (std::size_t i = 0; i < model->nodes.size(); ++i)
        if (static_cast<uint8_t>(model->nodes[i].node_class) > 3)
            in.fail("node_class", "values must be in [0, 3], got " +
                                      std::to_string(int(model->nodes[i].node_class)) +
                                      " at index " + std::to_string(i));
    return {std::move(model), {}};
}

struct ResultPy {
    py::array labels, cluster_ids;
    ClustersPy clusters;
    TerrainPy terrain;
    StageTimings timings;
    std::array<std::size_t, 4> class_counts{};
    double sensor_height = 0;
    std::string mount_note;
};

/// The stages of StageTimings, by name (Result.timings and the pickle state).
constexpr std::pair<const char*, double StageTimings::*> kStages[] = {
    {"preprocess", &StageTimings::preprocess},
    {"embedding", &StageTimings::embedding},
    {"node_fitting", &StageTimings::node_fitting},
    {"graph_search", &StageTimings::graph_search},
    {"ttmf", &StageTimings::ttmf},
    {"labelling", &StageTimings::labelling},
    {"ground_total", &StageTimings::ground_total},
    {"range_image", &StageTimings::range_image},
    {"horizontal", &StageTimings::horizontal},
    {"vertical", &StageTimings::vertical},
    {"clusters", &StageTimings::clusters},
    {"objects_total", &StageTimings::objects_total}};

py::dict timingsDict(const StageTimings& t) {
    py::dict d;
    for (const auto& [name, member] : kStages) d[name] = t.*member;
    d["total"] = t.ground_total + t.objects_total;
    return d;
}

/// (labels, cluster_ids, clusters' state, terrain's state, timings (kStages order), class counts
/// (kPointClassNames order), sensor_height, mount_note).
py::object resultState(const ResultPy& r) {
    py::list timings, counts;
    for (const auto& stage : kStages) timings.append(r.timings.*stage.second);
    for (const auto& c : kPointClassNames) counts.append(r.class_counts[int(c.value)]);
    return py::make_tuple(r.labels, r.cluster_ids, clustersState(r.clusters),
                          terrainState(r.terrain), py::tuple(timings), py::tuple(counts),
                          r.sensor_height, r.mount_note);
}

/// Checks sizes and types only: the arrays of a Result and its Clusters are writable, and an
/// edited one (own cluster ids, relabelled points) comes back as it was pickled.
ResultPy resultFromState(const py::object& state) {
    StateReader in("travel.Result", state, 8);
    ResultPy r;
    r.labels = in.array<uint8_t>("labels", {-1});
    const py::ssize_t n = r.labels.shape(0);
    r.cluster_ids = in.array<uint32_t>("cluster_ids", {n});
    r.clusters = clustersFromState(in.next(), in.context("clusters"));
    r.terrain = terrainFromState(in.next(), in.context("terrain"));
    StateReader timings(in.context("timings"), in.next(), std::size(kStages));
    for (const auto& [name, member] : kStages) r.timings.*member = timings.real(name);
    StateReader counts(in.context("class_counts"), in.next(), std::size(kPointClassNames));
    for (const auto& c : kPointClassNames)
        r.class_counts[int(c.value)] = static_cast<std::size_t>(counts.integer(c.name, 0, n));
    r.sensor_height = in.real("sensor_height");
    r.mount_note = in.text("mount_note");
    return r;
}

// ---- Pipeline ------------------------------------------------------------------------------

/// One travel::Pipeline with its input and output buffers; process() holds a per-instance lock
/// (not the GIL), so one Pipeline shared by threads serialises instead of mixing frames.
struct PipelinePy {
    explicit PipelinePy(const Params& params) : pipeline(params) {}
    Pipeline pipeline;
    PointCloud cloud;
    Result result;
    std::mutex mutex;
};

FrameInput frameInput(const py::object& attitude, const py::object& gravity,
                      const py::object& velocity, double reference_time) {
    FrameInput input;
    if (!std::isfinite(reference_time))  // as velocity's: NaN would silently turn deskew off
        throw py::value_error("reference_time: not finite");
    input.reference_time = reference_time;
    if (!attitude.is_none()) {
        const std::vector<double> r = fixedFrom(attitude, 9, "attitude (3x3 rotation)");
        Eigen::Matrix3d rotation;
        for (int i = 0; i < 9; ++i) rotation(i / 3, i % 3) = r[static_cast<std::size_t>(i)];
        if (!isUsableAttitude(rotation))  // the library would ignore it: a mistake here
            throw py::value_error(
                "attitude: not a rotation (orthonormal within 1e-3, determinant +1 expected)");
        input.vehicle_attitude = rotation;
    }
    if (!gravity.is_none()) {
        const std::vector<double> g = fixedFrom(gravity, 3, "gravity");
        input.gravity_in_sensor = Eigen::Vector3d(g[0], g[1], g[2]);
        if (!isUsableGravity(*input.gravity_in_sensor))
            throw py::value_error("gravity: the zero vector has no direction");
    }
    if (!velocity.is_none()) {
        const std::vector<double> v = fixedFrom(velocity, 6, "velocity (vx, vy, vz, wx, wy, wz)");
        input.linear_velocity = Eigen::Vector3d(v[0], v[1], v[2]);
        input.angular_velocity = Eigen::Vector3d(v[3], v[4], v[5]);
    }
    return input;
}

ResultPy process(PipelinePy& self, const py::object& points, const py::object& rings,
                 const py::object& times, const py::object& attitude, const py::object& gravity,
                 const py::object& velocity, double reference_time) {
    FrameInput input = frameInput(attitude, gravity, velocity, reference_time);
    const ScanPy* scan = py::isinstance<ScanPy>(points) ? &points.cast<const ScanPy&>() : nullptr;
    py::array array;
    PointsView view;
    std::vector<uint16_t> ring;
    std::vector<float> time;
    if (!scan) {
        array = pointsArray(points);
        view = viewOf(array);
        if (!rings.is_none()) ring = vectorFrom<uint16_t>(rings, view.n, "rings", "iu");
        if (!times.is_none()) {
            // Relative to reference_time, in double, before the library's float32: absolute
            // stamps (1.7e9 s, float32 step 128 s) would otherwise all round to the reference.
            const auto t = vectorFrom<double>(times, view.n, "times", "f");
            time.resize(t.size());
            for (std::size_t i = 0; i < t.size(); ++i)
                time[i] = static_cast<float>(t[i] - reference_time);
            input.reference_time = 0.0;
        }
    } else if (!rings.is_none() || !times.is_none()) {
        throw py::value_error(
            "rings and times come from the Scan; pass its points as an array "
            "to override them");
    }

    ResultPy out;
    std::vector<PointClass> labels;
    std::vector<uint32_t> cluster_ids;
    std::vector<ClusterSummary> clusters;
    {
        py::gil_scoped_release release;
        std::lock_guard<std::mutex> lock(self.mutex);
        const PointCloud* cloud = &self.cloud;
        if (scan) {
            cloud = &scan->cloud;
        } else {
            if (view.is_double)
                copyColumns<double>(view, self.cloud);
            else
                copyColumns<float>(view, self.cloud);
            self.cloud.ring = std::move(ring);
            self.cloud.time = std::move(time);
        }
        Result& r = self.result;
        self.pipeline.process(*cloud, input, r);
        out.timings = r.timings;
        out.class_counts = r.class_counts;
        out.sensor_height = r.sensor_height;
        out.mount_note = r.mount.message;
        out.terrain.model = std::make_shared<const TerrainModel>(r.terrain);
        // Taken while locked: the next call on this Pipeline refills the buffers.
        labels = std::move(r.labels), cluster_ids = std::move(r.cluster_id);
        r.labels.clear(), r.cluster_id.clear();
        clusters = r.clusters;
    }
    const auto n = static_cast<py::ssize_t>(labels.size());
    out.labels = adopt<uint8_t>(std::move(labels), {n});
    out.cluster_ids = adopt<uint32_t>(std::move(cluster_ids), {n});
    out.clusters = clustersFrom(clusters);
    return out;
}

// ---- Files and metrics ---------------------------------------------------------------------

ScanPy readScanPy(const std::string& path, const std::string& format) {
    ScanPy s;
    const ScanFormat f = scanFormatFromString(format);
    ScanFormat used = f;
    {
        py::gil_scoped_release release;
        used = readScan(path, s.cloud, f);
    }
    s.path = path, s.format = toString(used);
    return s;
}

/// An (N,) array-like of travel classes (0..3) as PointClass values.
std::vector<PointClass> classesFrom(const py::handle& labels, py::ssize_t n) {
    const auto v = vectorFrom<uint8_t>(labels, n, "labels", "iu", 0, 3);
    std::vector<PointClass> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out[i] = static_cast<PointClass>(v[i]);
    return out;
}

void writeLabels(const std::string& path, const py::handle& labels, const py::handle& cluster_ids) {
    const auto cls = classesFrom(labels, -1);
    const auto ids = vectorFrom<uint32_t>(cluster_ids, static_cast<py::ssize_t>(cls.size()),
                                          "cluster_ids", "iu");
    std::vector<uint32_t> encoded(cls.size());
    for (std::size_t i = 0; i < cls.size(); ++i) encoded[i] = encodeLabel(cls[i], ids[i]);
    try {
        writeLabelFile(path, encoded);
    } catch (const std::runtime_error& e) {  // the library's message names the file and why
        PyErr_SetString(PyExc_OSError, e.what());
        throw py::error_already_set();
    }
}

py::dict groundMetrics(const py::handle& labels, const py::handle& gt, const py::object& z,
                       double sensor_height, const std::string& protocol) {
    if (protocol != "A" && protocol != "B")
        throw py::value_error("protocol must be 'A' (Patchwork) or 'B' (Patchwork++), got '" +
                              protocol + "'");
    const auto pred = classesFrom(labels, -1);
    const auto n = static_cast<py::ssize_t>(pred.size());
    const auto truth = vectorFrom<uint32_t>(gt, n, "gt", "iu");
    const GroundProtocol p = protocol == "A" ? GroundProtocol::A : GroundProtocol::B;
    std::vector<float> heights;
    if (p == GroundProtocol::A) {
        if (z.is_none()) throw py::value_error("protocol A needs the points' z (sensor frame)");
        heights = vectorFrom<float>(z, n, "z", "fiu");
    }
    const ConfusionCounts c = countGround(pred, truth, heights, sensor_height, p);
    const GroundScores s = scoresFrom(c);
    py::dict d;
    d["precision"] = s.precision, d["recall"] = s.recall, d["f1"] = s.f1;
    d["accuracy"] = s.accuracy, d["tp"] = c.tp, d["fp"] = c.fp, d["tn"] = c.tn, d["fn"] = c.fn;
    return d;
}

py::dict objectMetrics(const py::handle& cluster_ids, const py::handle& labels,
                       const py::handle& gt, const py::handle& points,
                       const ObjectEvalOptions& options) {
    const auto pred = classesFrom(labels, -1);
    const auto n = static_cast<py::ssize_t>(pred.size());
    const auto ids = vectorFrom<uint32_t>(cluster_ids, n, "cluster_ids", "iu");
    const auto truth = vectorFrom<uint32_t>(gt, n, "gt", "iu");
    const py::array array = pointsArray(points);
    const PointsView view = viewOf(array);
    if (view.n != n) throw py::value_error("points: expected " + std::to_string(n) + " rows");
    PointCloud cloud;
    view.is_double ? copyColumns<double>(view, cloud) : copyColumns<float>(view, cloud);
    const ObjectScores s = evaluateObjects(ids, pred, truth, cloud, options);
    py::list instances;
    for (const InstanceScore& i : s.instances)
        instances.append(py::dict(py::arg("semantic") = i.semantic,
                                  py::arg("instance") = i.instance, py::arg("points") = i.points,
                                  py::arg("coverage") = i.coverage, py::arg("purity") = i.purity,
                                  py::arg("best_cluster") = i.best_cluster));
    const SegmentationEntropy& e = s.entropy;
    return py::dict(
        py::arg("ose_sum") = e.ose_sum, py::arg("use_sum") = e.use_sum,
        py::arg("ose_mean") = e.ose_mean, py::arg("use_mean") = e.use_mean,
        py::arg("gt_objects") = e.num_gt_objects, py::arg("clusters") = e.num_clusters,
        py::arg("scored_points") = e.num_points, py::arg("mean_coverage") = s.mean_coverage,
        py::arg("mean_purity") = s.mean_purity, py::arg("clustered") = s.clustered,
        py::arg("split") = s.split, py::arg("merged") = s.merged, py::arg("instances") = instances);
}

/// Milliseconds of each of `repeats` C++ calls Pipeline::process(scan) on `self`'s pipeline and
/// result buffers (reused, as a C++ caller does), with no Python in the loop: the reference the
/// binding's overhead is measured against (python/bench/overhead.py).
std::vector<double> benchCpp(PipelinePy& self, const ScanPy& scan, int repeats) {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(self.mutex);
    std::vector<double> ms;
    for (int k = 0; k < repeats; ++k) {
        const auto start = std::chrono::steady_clock::now();
        self.pipeline.process(scan.cloud, FrameInput{}, self.result);
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
    return ms;
}

}  // namespace

void bindPipeline(py::module_& m) {
    py::class_<ScanPy>(m, "Scan", R"doc(
A scan read by read_scan(), kept in the library's layout: Pipeline.process(scan) uses it without
any copy. `points` builds an (N, 4) float32 array (x, y, z, intensity) on each access.
)doc")
        .def("__len__", [](const ScanPy& s) { return s.cloud.size(); })
        .def_readonly("path", &ScanPy::path)
        .def_readonly("format", &ScanPy::format, "The format read: kitti, nuscenes, pcd or ply.")
        .def_property_readonly("points", &scanPoints,
                               "(N, 4) float32: x, y, z, intensity (a copy).")
        .def_property_readonly("rings", &scanRings,
                               "(N,) uint16 laser ring (0 = lowest), or None when the file has "
                               "none.")
        .def_property_readonly("times", &scanTimes,
                               "(N,) float32 per-point time [s], or None when the file has none.")
        .def(py::pickle(&scanState, &scanFromState))
        .def("__repr__", [](const ScanPy& s) {
            return "travel.Scan('" + s.path + "', format='" + s.format + "', " +
                   std::to_string(s.cloud.size()) + " points)";
        });

    py::class_<ClustersPy> clusters(m, "Clusters", R"doc(
One row per cluster, ordered by id (ids[k] == k + 1). Coordinates in the aligned frame (sensor
origin, z up against gravity). Boxes: axis-aligned (aabb_min, aabb_max) and oriented (obb_center,
obb_extent = length >= width, height; obb_yaw [rad] of the length axis). ground_z: terrain height
under the centroid (NaN if unknown); height_above_ground: of the highest point above it [m].
)doc");
    clusters.def("__len__", [](const ClustersPy& c) { return c.size; })
        .def(py::pickle(&clustersState, [](const py::object& state) {
            return clustersFromState(state, "travel.Clusters");
        }));
    forEachClusterArray([&](const char* name, py::array ClustersPy::*member, const char* doc,
                            auto&&...) { clusters.def_readonly(name, member, doc); });

    using T = TerrainModel;
    auto nodes = [](auto get) { return [get](const TerrainPy& t) { return get(*t.model); }; };
    // A per-node array, built on its first read and kept: later reads return the same array.
    int slots = 0;
    auto cached = [&slots](auto get) {
        return [slot = slots++, get](const TerrainPy& t) {
            py::object& array = t.arrays[slot];
            if (!array) {
                // Read-only: the Terrain's methods (node_at, height_above_ground) read the model,
                // which an edit of the array would not change.
                array = get(*t.model);
                array.attr("setflags")(py::arg("write") = false);
            }
            return array;
        };
    };
    py::class_<TerrainPy> terrain(m, "Terrain", R"doc(
The terrain model of a frame (paper Sec. III): a tri-grid of square cells of side `resolution`,
4 triangular nodes per cell, node index = 4 * (iy * cells_per_side + ix) + triangle (0 east,
1 north, 2 west, 3 south). Aligned frame: sensor origin, z up; ground near z = -sensor_height.
Arrays have one row per node (M = 4 * cells_per_side**2), built when first read and kept
(each read returns the same array), read-only (copy one to edit it).
)doc");
    terrain.def("__len__", [](const TerrainPy& t) { return t.model->nodes.size(); })
        .def_property_readonly("resolution", nodes([](const T& t) { return t.resolution; }))
        .def_property_readonly("cells_per_side", nodes([](const T& t) { return t.cells_per_side; }))
        .def_property_readonly("origin_xy", nodes([](const T& t) { return t.origin_xy; }),
                               "x and y of the grid's lower-left corner")
        .def_property_readonly("seed_node", nodes([](const T& t) { return t.seed_node; }),
                               "start node of the first search (-1: none)")
        .def_property_readonly("num_components",
                               nodes([](const T& t) { return t.num_components; }));
    forEachNodeArray([&](const char* name, const char* doc, auto col, auto get, auto) {
        using Col = decltype(col);
        if (doc)
            terrain.def_property_readonly(name, cached([get](const T& t) {
                                              return columns<typename Col::Type, Col::cols>(t.nodes,
                                                                                            get);
                                          }),
                                          doc);
    });
    terrain
        .def_property_readonly(
            "corners", cached([](const T& t) { return triangleCornersXYZ(t); }),
            "(M, 3, 3) float32 the triangle's corners (cell centre first, counter-clockwise): "
            "x, y and TTMF's corner height z (NaN where no traversable node voted)")
        .def(
            "node_at", [](const TerrainPy& t, float x, float y) { return t.model->nodeAt(x, y); },
            py::arg("x"), py::arg("y"), "Node index holding (x, y), -1 outside the grid.")
        .def(
            "height_above_ground",
            [](const TerrainPy& t, const py::handle& points) {
                const py::array array = pointsArray(points);
                const PointsView v = viewOf(array);
                PointCloud c;
                v.is_double ? copyColumns<double>(v, c) : copyColumns<float>(v, c);
                std::vector<float> h(c.size());
                for (std::size_t i = 0; i < c.size(); ++i)
                    h[i] = t.model->heightAboveGround(c.x[i], c.y[i], c.z[i]);
                const auto n = static_cast<py::ssize_t>(h.size());
                return adopt<float>(std::move(h), {n});
            },
            py::arg("points"),
            "(N,) float32 height of aligned-frame points above the local ground (lowest of the "
            "ground planes of the point's cell and its 4 neighbours), NaN where unknown.")
        .def(py::pickle(&terrainState, [](const py::object& state) {
            return terrainFromState(state, "travel.Terrain");
        }));

    py::class_<ResultPy>(m, "Result", R"doc(
The result of one frame; arrays are indexed like the input points and owned by the Result.
labels (N,) uint8: 0 invalid (NaN / inf / zero / out of range), 1 ground, 2 non-ground,
3 outlier (below ground). cluster_ids (N,) uint32, 0 = no cluster. Pickles exactly (so it comes
back from a worker process), as do Scan, Clusters and Terrain.
)doc")
        .def_readonly("labels", &ResultPy::labels, "(N,) uint8 class per point")
        .def_readonly("cluster_ids", &ResultPy::cluster_ids, "(N,) uint32, 0 = no cluster")
        .def_property_readonly(
            "ground_mask",
            [](const ResultPy& r) { return r.labels.attr("__eq__")(1).cast<py::array>(); },
            "(N,) bool labels == GROUND")
        .def_readonly("clusters", &ResultPy::clusters)
        .def_readonly("terrain", &ResultPy::terrain)
        .def_property_readonly(
            "timings", [](const ResultPy& r) { return timingsDict(r.timings); },
            "Milliseconds per stage of this frame (and 'total').")
        .def_property_readonly("class_counts",
                               [](const ResultPy& r) {
                                   py::dict d;
                                   for (const auto& c : kPointClassNames)
                                       d[c.name] = r.class_counts[int(c.value)];
                                   return d;
                               })
        .def_readonly("sensor_height", &ResultPy::sensor_height,
                      "h_s used for this frame (the estimate once an 'auto' height is known)")
        .def_readonly("mount_note", &ResultPy::mount_note,
                      "News about the sensor mount on the frame it happened ('' otherwise): an "
                      "'auto' estimate, or configured values far from the ground")
        .def("__len__", [](const ResultPy& r) { return r.labels.size(); })
        .def("__repr__",
             [](const ResultPy& r) {
                 return "travel.Result(" + std::to_string(r.labels.size()) + " points, " +
                        std::to_string(r.class_counts[1]) + " ground, " +
                        std::to_string(r.clusters.size) + " clusters)";
             })
        .def(py::pickle(&resultState, &resultFromState));

    py::class_<PipelinePy>(m, "Pipeline", R"doc(
The TRAVEL pipeline: ground segmentation, then object clustering of the non-ground points.
Keep one per sensor stream and reuse it (buffers are reused; `auto` mount values are estimated on
the first frames and kept). Pipelines share nothing: one per thread runs in parallel (process
releases the GIL); one Pipeline used by several threads serialises its calls.
)doc")
        .def(py::init<const Params&>(), py::arg("params") = Params{},
             "Validates params (ConfigError naming the first offending parameter).")
        .def("process", &process, py::arg("points"), py::arg("rings") = py::none(),
             py::arg("times") = py::none(), py::arg("attitude") = py::none(),
             py::arg("gravity") = py::none(), py::arg("velocity") = py::none(),
             py::arg("reference_time") = 0.0, R"doc(
Segments one frame and returns a Result.

points: (N, 3) or (N, 4) float32 or float64 array (x, y, z[, intensity]) in the sensor frame, any
  strides (read in place, copied once into the library's buffers), or a travel.Scan (no copy).
  Points with NaN / inf coordinates, all-zero points and points outside [min_range, max_range]
  are labelled 0 (invalid); nothing is dropped, nothing raises.
rings: optional (N,) integer laser ring (0 = lowest), values in [0, 65535].
times: optional (N,) float per-point time [s] (same clock as reference_time, absolute stamps
  fine: taken relative to it in double), for deskew.
attitude: optional 3x3 rotation vehicle -> gravity-aligned (roll and pitch level the frame).
gravity: optional 3-vector, the gravity direction measured in the sensor frame (instead).
velocity: optional (vx, vy, vz, wx, wy, wz), sensor frame [m/s, rad/s], for deskew with times.
Raises ValueError for a wrong shape, dtype or size.
)doc")
        .def_property_readonly(
            "params",
            [](PipelinePy& p) {
                // Under the lock, as process() (which writes 'auto' estimates) runs: waiting for
                // it without the GIL, so that the running call can finish.
                py::gil_scoped_release release;
                std::lock_guard<std::mutex> lock(p.mutex);
                return p.pipeline.params();
            },
            "The parameters in use ('auto' values replaced by their estimates once known).");

    m.def("read_scan", &readScanPy, py::arg("path"), py::arg("format") = "auto", R"doc(
Reads a scan with the library's reader (the apps' one): format auto, kitti, nuscenes, pcd or ply.
`auto` decides from the name, folder, first line or size, never by guessing silently. Raises
InputError (a ValueError) naming the file when it is missing, malformed or has no finite point.
)doc");
    m.def("_write_labels", &writeLabels, py::arg("path"), py::arg("labels"),
          py::arg("cluster_ids"));
    m.def(
        "read_labels",
        [](const std::string& path) {
            std::vector<uint32_t> v = readLabelFile(path, kAnyLabelCount);
            const auto n = static_cast<py::ssize_t>(v.size());
            return adopt<uint32_t>(std::move(v), {n});
        },
        py::arg("path"), "A .label file (SemanticKITTI or travel-kitti) as (N,) uint32.");
    m.def("_ground_metrics", &groundMetrics);
    py::class_<ObjectEvalOptions>(m, "_ObjectEvalOptions")
        .def(py::init<>())
        .def_readwrite("gt_cluster_distance", &ObjectEvalOptions::gt_cluster_distance)
        .def_readwrite("min_gt_object_points", &ObjectEvalOptions::min_gt_object_points)
        .def_readwrite("min_instance_points", &ObjectEvalOptions::min_instance_points)
        .def_readwrite("entropy_on_predicted_nonground",
                       &ObjectEvalOptions::entropy_on_predicted_nonground);
    m.def("_object_metrics", &objectMetrics);
    m.def("_bench_cpp", &benchCpp);
}

}  // namespace travel::python

PYBIND11_MODULE(_travel, m) {
    m.doc() = "TRAVEL for MRPT: traversable ground and object segmentation of LiDAR scans.";
    travel::python::bindParams(m);
    travel::python::bindPipeline(m);
}
