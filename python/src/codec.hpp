// Templates over the library's tables that turn a message into a Python dict
// (the shape of the command-line tool's JSON line) and a dict back into a
// message. Nothing here names a message: every protocol module calls these
// for the alternatives of its std::variant, so a message added to a
// protocol appears in Python with no change to the binding.
#pragma once

#include <pybind11/pybind11.h>

#include <robowire/core/fields.hpp>
#include <robowire/core/flag_bits.hpp>
#include <robowire/core/table.hpp>
#include <robowire/reflect.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "schema.hpp"

namespace rwpy {

namespace py = pybind11;
using robowire::errc;
using robowire::wire_kind;

// ---------------------------------------------------------------- Python objects
// A new reference as a py::object.
inline py::object steal(PyObject* o) {
    if (!o) throw py::error_already_set();
    return py::reinterpret_steal<py::object>(o);
}
// An interned str that lives as long as the process (kept in caches).
inline PyObject* interned(std::string_view s) {
    PyObject* o = PyUnicode_FromStringAndSize(s.data(), static_cast<Py_ssize_t>(s.size()));
    if (!o) throw py::error_already_set();
    PyUnicode_InternInPlace(&o);
    return o;
}
inline py::str str_of(std::string_view s) { return py::reinterpret_steal<py::str>(interned(s)); }
// d[key] = value (value is stolen).
inline void set_item(PyObject* d, PyObject* key, PyObject* value) {
    if (!value) throw py::error_already_set();
    const int rc = PyDict_SetItem(d, key, value);
    Py_DECREF(value);
    if (rc != 0) throw py::error_already_set();
}

// "01 6D 50", as the command-line tool prints bytes.
inline std::string hex_of(std::span<const std::uint8_t> b) {
    static constexpr char digits[] = "0123456789ABCDEF";
    std::string s;
    s.reserve(b.size() * 3);
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (i) s += ' ';
        s += digits[b[i] >> 4];
        s += digits[b[i] & 15];
    }
    return s;
}

// Rounded to 15 significant digits, as the command-line tool does (13.000000000000002 -> 13).
inline double tidy(double v) {
    if (!std::isfinite(v)) return v;
    char b[40];
    const auto r = std::to_chars(b, b + sizeof b, v, std::chars_format::general, 15);
    double out = v;
    std::from_chars(b, r.ptr, out);
    return out;
}

// A str as UTF-8 for looking up a name: lone surrogates, which no name
// holds, are spelled as Python escapes so that the lookup fails with the
// caller's KeyError or ValueError (never a UnicodeEncodeError).
inline std::string name_of(PyObject* o) {
    Py_ssize_t n = 0;
    if (const char* c = PyUnicode_AsUTF8AndSize(o, &n)) return {c, static_cast<std::size_t>(n)};
    PyErr_Clear();
    PyObject* b = PyUnicode_AsEncodedString(o, "utf-8", "backslashreplace");
    if (!b) throw py::error_already_set();
    std::string out(PyBytes_AS_STRING(b), static_cast<std::size_t>(PyBytes_GET_SIZE(b)));
    Py_DECREF(b);
    return out;
}
// A str's bytes to send: UTF-8, undecodable bytes read with surrogateescape
// sent back as they were; ValueError naming `what` for other lone surrogates.
inline py::bytes utf8_bytes(PyObject* o, std::string_view what) {
    PyObject* b = PyUnicode_AsEncodedString(o, "utf-8", "surrogateescape");
    if (!b) {
        PyErr_Clear();
        throw py::value_error(std::string(what) + ": not text that UTF-8 can carry (a lone surrogate)");
    }
    return py::reinterpret_steal<py::bytes>(b);
}

// A value quoted in a message: at most 40 characters ("xxx...").
inline std::string shorten(std::string s) {
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return s;
}

// ---------------------------------------------------------------- errors
// The Python classes robowire.DecodeError and robowire.EncodeError (module init sets them).
struct error_classes {
    PyObject* decode = nullptr;
    PyObject* encode = nullptr;
};
inline error_classes& classes() {
    static error_classes c;
    return c;
}

// Raises cls(text, code, offset, field, message, notes).
[[noreturn]] inline void raise(PyObject* cls, std::string_view text, std::optional<errc> code, std::size_t offset,
                               std::string_view field, std::string_view message, const std::vector<std::string>& notes = {}) {
    py::list n;
    for (const auto& s : notes) n.append(py::str(s));
    py::object inst = py::reinterpret_borrow<py::object>(cls)(
        py::str(std::string(text)), code ? py::object(py::str(std::string(robowire::schema::errc_name(*code)))) : py::object(py::none()),
        py::int_(offset), field.empty() ? py::object(py::none()) : py::object(py::str(std::string(field))),
        message.empty() ? py::object(py::none()) : py::object(py::str(std::string(message))), n);
    PyErr_SetObject(cls, inst.ptr());
    throw py::error_already_set();
}

// An integer argument of a unit helper as T: ValueError naming the
// argument and T's range when it does not fit ("battery_volts: raw = 256:
// value out of range (valid 0..255)"), EncodeError value_out_of_range from
// helpers that build a raw value (`encode`), the same error as for a value
// T holds that the helper refuses ("soc_from_basis_points: basis_points:
// value out of range").
template <class T>
T int_arg(const py::int_& o, std::string_view fn, std::string_view arg, bool encode = false) {
    int overflow = 0;
    const long long x = PyLong_AsLongLongAndOverflow(o.ptr(), &overflow);
    if (x == -1 && PyErr_Occurred()) throw py::error_already_set();
    if (overflow == 0 && std::in_range<T>(x)) return static_cast<T>(x);
    const std::string tail = ": " + std::string(robowire::to_string(errc::value_out_of_range)) + " (valid " +
                             std::to_string(std::numeric_limits<T>::min()) + ".." + std::to_string(std::numeric_limits<T>::max()) + ")";
    const std::string given = py::repr(o).cast<std::string>();
    if (!encode)
        throw py::value_error(std::string(fn) + ": " + std::string(arg) + " = " + (given.size() > 40 ? given.substr(0, 37) + "..." : given) +
                              tail);
    raise(classes().encode, std::string(fn) + ": " + std::string(arg) + ": " + std::string(robowire::to_string(errc::value_out_of_range)),
          errc::value_out_of_range, 0, {}, {});
}

// describe_error's line for an error of message M.
template <class M>
std::string describe(const robowire::error& e) {
    char buf[160];
    const auto s = robowire::describe_error<M>(e, buf);
    return std::string(s);
}
// Raises DecodeError / EncodeError for error e of message M.
template <class M>
[[noreturn]] void raise_for(PyObject* cls, const robowire::error& e, const std::vector<std::string>& notes = {}) {
    const bool length = e.code == errc::too_short || e.code == errc::too_long;
    const auto f = robowire::field_at<M>(e);
    raise(cls, describe<M>(e), e.code, e.offset, length ? std::string_view{} : f.name,
          robowire::table_v<M>.name, notes);
}

// ---------------------------------------------------------------- per-message caches
template <class F>
using element_t = typename F::element_type;

// Flag bits [lo, lo+width) of a flag byte: its name and its values' names.
struct flag_key {
    robowire::flag_bit bit;
    PyObject* name;
    std::array<PyObject*, 4> values;  // nullptr: unnamed
};
// A field's dict keys (its name, its physical value's, its flag bits') and flag bits.
struct field_keys {
    PyObject* name;
    PyObject* physical;
    PyObject* bits;
    std::vector<flag_key> flags;
    PyObject* unit = nullptr;    // the unit's name (fields with a unit)
    bool exact = false;          // physical = raw (scale 1, offset 0): no rounding needed
    std::vector<double> by_byte; // one-byte fields: the physical value of each raw byte, worked out once
};

template <class M>
const std::vector<field_keys>& keys_of() {
    static const auto* keys = [] {
        auto* v = new std::vector<field_keys>;  // kept for the process (no destructor after Python is gone)
        robowire::for_each_field<M>([&](const auto& f) {
            std::string n(f.name), phys;
            if (n.size() > 4 && n.compare(n.size() - 4, 4, "_raw") == 0) phys = n.substr(0, n.size() - 4);
            else phys = n + "_physical";
            field_keys k{interned(n), interned(phys), interned(n + "_bits"), {}, nullptr, false, {}};
            using F = std::remove_cvref_t<decltype(f)>;
            using E = element_t<F>;
            if (!f.unit.name.empty()) {
                k.unit = interned(f.unit.name);
                k.exact = f.unit.scale == 1.0 && f.unit.offset == 0.0;
                if constexpr (robowire::value_kind_v<F> == robowire::value_kind::integer && sizeof(E) == 1) {
                    if (!k.exact) {
                        k.by_byte.resize(256);
                        for (unsigned b = 0; b < 256; ++b) {
                            const auto raw = static_cast<E>(static_cast<std::uint8_t>(b));
                            k.by_byte[b] = tidy(robowire::physical_of(f, raw));
                        }
                    }
                }
            }
            robowire::for_each_flag_bit<M>(f.name, [&](const robowire::flag_bit& b) {
                flag_key fk{b, interned(b.name), {}};
                for (std::size_t i = 0; i < 4; ++i) {
                    const auto name = robowire::flag_value_name(b, static_cast<unsigned>(i));
                    fk.values[i] = name.empty() ? nullptr : interned(name);
                }
                k.flags.push_back(fk);
            });
            v->push_back(std::move(k));
        });
        return v;
    }();
    return *keys;
}

// Enum names as Python strings, by code.
template <class E>
PyObject* enum_str(E e) {
    static const auto* names = [] {
        auto* v = new std::vector<std::pair<E, PyObject*>>;
        for (const auto& entry : robowire::enum_table_v<E>) v->emplace_back(entry.value, interned(entry.name));
        return v;
    }();
    for (const auto& [code, s] : *names)
        if (code == e) {
            Py_INCREF(s);
            return s;
        }
    return PyLong_FromLong(static_cast<long>(e));  // not reached after a decode
}

inline PyObject* unit_key() {
    static PyObject* k = interned("unit");
    return k;
}
inline PyObject* value_key() {
    static PyObject* k = interned("value");
    return k;
}

// ---------------------------------------------------------------- message -> dict
template <class M>
PyObject* fields_dict(const M& m);

// One element as a new reference.
template <class F, class E>
PyObject* element_py(const E& v) {
    if constexpr (F::kind == wire_kind::record) {
        return fields_dict(v);
    } else if constexpr (std::is_same_v<E, bool>) {
        return PyBool_FromLong(v ? 1 : 0);
    } else if constexpr (std::is_enum_v<E>) {
        return enum_str(v);
    } else if constexpr (std::is_floating_point_v<E>) {
        return PyFloat_FromDouble(static_cast<double>(v));
    } else if constexpr (std::is_integral_v<E>) {
        return PyLong_FromLongLong(static_cast<long long>(v));
    } else if constexpr (requires { v.view(); }) {  // text
        const auto s = v.view();
        return PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "surrogateescape");
    } else {  // a byte tail, as the tool's hex
        const std::string h = hex_of(v.span());
        return PyUnicode_FromStringAndSize(h.data(), static_cast<Py_ssize_t>(h.size()));
    }
}

// The physical value of raw value v of a field with a unit, rounded as the tool rounds it.
template <class F, class E>
double physical_of(const field_keys& k, const F& f, E v) {
    if (k.exact) return static_cast<double>(v);
    if constexpr (sizeof(E) == 1) return k.by_byte[static_cast<std::uint8_t>(v)];
    else return tidy(robowire::physical_of(f, static_cast<std::int64_t>(v)));
}

template <class F>
constexpr bool has_physical() {
    return robowire::value_kind_v<F> == robowire::value_kind::integer;
}

template <class M>
PyObject* fields_dict(const M& m) {
    PyObject* d = PyDict_New();
    if (!d) throw py::error_already_set();
    py::object owner = py::reinterpret_steal<py::object>(d);
    const auto& keys = keys_of<M>();
    std::size_t index = 0;
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        using E = element_t<F>;
        const field_keys& k = keys[index++];
        const auto& member = m.*(f.member);
        const auto* value = [&]() {
            if constexpr (F::is_optional) return member ? &*member : nullptr;
            else return &member;
        }();
        if (!value) {
            Py_INCREF(Py_None);
            set_item(d, k.name, Py_None);
            return;
        }
        const bool with_unit = !f.unit.name.empty();
        if constexpr (F::is_array) {
            PyObject* list = PyList_New(static_cast<Py_ssize_t>(F::count));
            if (!list) throw py::error_already_set();
            for (std::size_t i = 0; i < F::count; ++i) {
                PyObject* e = element_py<F>((*value)[i]);
                if (!e) {
                    Py_DECREF(list);
                    throw py::error_already_set();
                }
                PyList_SET_ITEM(list, static_cast<Py_ssize_t>(i), e);
            }
            set_item(d, k.name, list);
            if constexpr (has_physical<F>()) {
                if (with_unit) {
                    PyObject* phys = PyList_New(static_cast<Py_ssize_t>(F::count));
                    if (!phys) throw py::error_already_set();
                    for (std::size_t i = 0; i < F::count; ++i)
                        PyList_SET_ITEM(phys, static_cast<Py_ssize_t>(i), PyFloat_FromDouble(physical_of(k, f, (*value)[i])));
                    PyObject* pd = PyDict_New();
                    set_item(pd, value_key(), phys);
                    Py_INCREF(k.unit);
                    set_item(pd, unit_key(), k.unit);
                    set_item(d, k.physical, pd);
                }
            }
        } else {
            set_item(d, k.name, element_py<F>(*value));
            if constexpr (has_physical<F>()) {
                if (with_unit) {
                    PyObject* pd = PyDict_New();
                    set_item(pd, value_key(), PyFloat_FromDouble(physical_of(k, f, *value)));
                    Py_INCREF(k.unit);
                    set_item(pd, unit_key(), k.unit);
                    set_item(d, k.physical, pd);
                }
                if constexpr (robowire::has_flag_bits<M>) {
                    const auto& bits = k.flags;
                    if (!bits.empty()) {
                        PyObject* bd = PyDict_New();
                        if (!bd) throw py::error_already_set();
                        const auto raw = static_cast<unsigned>(static_cast<std::make_unsigned_t<E>>(*value));
                        for (const auto& b : bits) {
                            const unsigned v = robowire::flag_value(b.bit, raw);
                            if (b.bit.width == 1) {
                                set_item(bd, b.name, PyBool_FromLong(v ? 1 : 0));
                            } else if (v < 4 && b.values[v]) {
                                Py_INCREF(b.values[v]);
                                set_item(bd, b.name, b.values[v]);
                            } else {
                                set_item(bd, b.name, PyUnicode_FromString(std::to_string(v).c_str()));
                            }
                        }
                        set_item(d, k.bits, bd);
                    }
                }
            }
        }
    });
    return owner.release().ptr();
}

// {"type": "message", "protocol": ..., "message": ..., "fields": {...}}
template <class M>
py::dict message_dict(PyObject* protocol, const M& m) {
    static PyObject* type_key = interned("type");
    static PyObject* message_value = interned("message");
    static PyObject* protocol_key = interned("protocol");
    static PyObject* message_key = interned("message");
    static PyObject* fields_key = interned("fields");
    static PyObject* name = interned(robowire::table_v<M>.name);
    py::dict d;
    PyObject* p = d.ptr();
    Py_INCREF(message_value);
    set_item(p, type_key, message_value);
    Py_INCREF(protocol);
    set_item(p, protocol_key, protocol);
    Py_INCREF(name);
    set_item(p, message_key, name);
    set_item(p, fields_key, fields_dict(m));
    return d;
}
template <class V>
py::dict variant_dict(PyObject* protocol, const V& v) {
    return std::visit([&](const auto& m) { return message_dict(protocol, m); }, v);
}

// ---------------------------------------------------------------- dict -> message
// Where a value goes, for messages only (built into text on an error):
// "set_led_status" . "colors" [1] . "g".
struct path {
    const path* parent = nullptr;
    std::string_view name{};
    std::size_t index = static_cast<std::size_t>(-1);  // array element, or none
    std::string str() const {
        std::string s = parent ? parent->str() + "." : std::string();
        s += name;
        if (index != static_cast<std::size_t>(-1)) s += "[" + std::to_string(index) + "]";
        return s;
    }
};

inline std::string type_name(PyObject* o) { return Py_TYPE(o)->tp_name; }

// Raises EncodeError for a value of field f that cannot be encoded, with
// describe_error's line for Top ("maneuver.pitch: value out of range (valid
// -100..100 %) at byte 7"): the same text as the library's own encode
// error. .field is `path` without the array indices and the message
// ("colors.g" inside a record); a note gives what the line cannot (the
// capacity of a text, the range of a record's member).
template <class Top, class F>
[[noreturn]] void field_error(const F& f, const std::string& path, errc code, std::size_t offset) {
    std::string name;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i] == '[') i = path.find(']', i);
        else name += path[i];
    }
    const auto dot = name.find('.');
    const std::string field = dot == std::string::npos ? std::string() : name.substr(dot + 1);
    std::vector<std::string> notes;
    if (code == errc::value_out_of_range) {
        using E = element_t<F>;
        if constexpr (F::kind == wire_kind::text) {
            notes.push_back(field + " holds up to " + std::to_string(E::capacity()) + " bytes of UTF-8");
        } else if constexpr (std::is_floating_point_v<E>) {
            notes.push_back(field + " holds a 32-bit float");
        } else if constexpr (std::is_integral_v<E>) {
            if (robowire::field_at<Top>(offset).name != field) {  // a record's member: the line names the record
                std::string valid = field + ": valid " + std::to_string(f.valid.min) + ".." + std::to_string(f.valid.max);
                if (!f.unit.name.empty()) valid += f.unit.raw_is_physical ? " " + std::string(f.unit.name) : std::string(" raw");
                notes.push_back(valid);
            }
        }
    }
    raise(classes().encode, describe<Top>(robowire::error{code, static_cast<std::uint16_t>(offset)}), code, offset, field,
          robowire::table_v<Top>.name, notes);
}

template <class Top, class M>
void fill(M& m, PyObject* dict, std::size_t base, const path* parent, bool ignore_derived);

// Reads one element from `o` into v.
template <class Top, class F, class E>
void read_element(const F& f, E& v, PyObject* o, const path& at, std::size_t offset, bool ignore_derived) {
    if constexpr (F::kind == wire_kind::record) {
        if (!PyDict_Check(o)) throw py::type_error(at.str() + ": expected a dict of " + std::string(robowire::table_v<E>.name) +
                                                   " fields, got " + type_name(o));
        fill<Top>(v, o, offset, &at, ignore_derived);
    } else if constexpr (std::is_same_v<E, bool>) {
        if (!PyLong_Check(o)) throw py::type_error(at.str() + ": expected a bool, got " + type_name(o));
        const long x = PyLong_AsLong(o);
        if (x == -1 && PyErr_Occurred()) PyErr_Clear();
        if (x != 0 && x != 1) field_error<Top>(f, at.str(), errc::value_out_of_range, offset);
        v = x == 1;
    } else if constexpr (std::is_enum_v<E>) {
        if (PyUnicode_Check(o)) {
            const auto e = robowire::enum_from_name<E>(name_of(o));
            if (!e) field_error<Top>(f, at.str(), errc::invalid_enum, offset);
            v = *e;
        } else if (PyLong_Check(o)) {
            int overflow = 0;
            const long long x = PyLong_AsLongLongAndOverflow(o, &overflow);
            using U = std::underlying_type_t<E>;
            if (overflow || x < std::numeric_limits<U>::min() || x > std::numeric_limits<U>::max() ||
                !robowire::is_valid_enum(static_cast<E>(static_cast<U>(x))))
                field_error<Top>(f, at.str(), errc::invalid_enum, offset);
            v = static_cast<E>(static_cast<U>(x));
        } else {
            throw py::type_error(at.str() + ": expected a name (str) or code (int), got " + type_name(o));
        }
    } else if constexpr (std::is_floating_point_v<E>) {
        if (!PyFloat_Check(o) && !PyLong_Check(o)) throw py::type_error(at.str() + ": expected a float, got " + type_name(o));
        const double x = PyFloat_AsDouble(o);
        if (x == -1.0 && PyErr_Occurred()) {  // an int too large for a double
            PyErr_Clear();
            field_error<Top>(f, at.str(), errc::value_out_of_range, offset);
        }
        if (std::isfinite(x) && std::fabs(x) > static_cast<double>(std::numeric_limits<E>::max()))
            field_error<Top>(f, at.str(), errc::value_out_of_range, offset);
        v = static_cast<E>(x);
    } else if constexpr (std::is_integral_v<E>) {
        if (!PyLong_Check(o)) throw py::type_error(at.str() + ": expected an int, got " + type_name(o));
        int overflow = 0;
        const long long x = PyLong_AsLongLongAndOverflow(o, &overflow);
        if (x == -1 && PyErr_Occurred()) throw py::error_already_set();
        if (overflow || x < f.valid.min || x > f.valid.max || !std::in_range<E>(x))
            field_error<Top>(f, at.str(), errc::value_out_of_range, offset);
        v = static_cast<E>(x);
    } else if constexpr (requires { v.view(); }) {  // text
        if (!PyUnicode_Check(o)) throw py::type_error(at.str() + ": expected a str, got " + type_name(o));
        const py::bytes utf8 = utf8_bytes(o, at.str());
        const std::string_view s(PyBytes_AS_STRING(utf8.ptr()), static_cast<std::size_t>(PyBytes_GET_SIZE(utf8.ptr())));
        const auto t = E::make(s);
        if (!t) field_error<Top>(f, at.str(), errc::value_out_of_range, offset);
        v = *t;
    } else {  // a byte tail: bytes-like, or hex text as decode gives it
        py::object raw;
        if (PyUnicode_Check(o)) {
            static PyObject* fromhex = PyObject_GetAttrString(reinterpret_cast<PyObject*>(&PyBytes_Type), "fromhex");
            PyObject* b = PyObject_CallOneArg(fromhex, o);
            if (!b) {
                PyErr_Clear();
                throw py::value_error(at.str() + ": not hex bytes: " + py::str(o).cast<std::string>());
            }
            raw = steal(b);
        } else if (PyObject_CheckBuffer(o)) {
            raw = steal(PyBytes_FromObject(o));
        } else {
            throw py::type_error(at.str() + ": expected bytes or hex text, got " + type_name(o));
        }
        const auto* p = reinterpret_cast<const std::uint8_t*>(PyBytes_AS_STRING(raw.ptr()));
        const auto x = E::from(std::span<const std::uint8_t>(p, static_cast<std::size_t>(PyBytes_GET_SIZE(raw.ptr()))));
        if (!x) field_error<Top>(f, at.str(), errc::capacity_exceeded, offset);
        v = *x;
    }
}

// Reads field f (an array: a list or tuple of exactly its count).
template <class Top, class F, class T>
void read_field(const F& f, T& value, PyObject* o, std::size_t base, const path& at, bool ignore_derived) {
    if constexpr (F::is_array) {
        if (!PyList_Check(o) && !PyTuple_Check(o))
            throw py::type_error(at.str() + ": expected a list of " + std::to_string(F::count) + " values, got " + type_name(o));
        const auto n = static_cast<std::size_t>(PySequence_Fast_GET_SIZE(o));
        if (n != F::count)
            throw py::value_error(at.str() + ": " + std::to_string(n) + (n == 1 ? " value" : " values") + " given, " +
                                  std::to_string(F::count) + " expected");
        PyObject** items = PySequence_Fast_ITEMS(o);
        for (std::size_t i = 0; i < F::count; ++i)
            read_element<Top>(f, value[i], items[i], path{at.parent, at.name, i}, base + f.offset + i * F::element_size, ignore_derived);
    } else {
        read_element<Top>(f, value, o, at, base + f.offset, ignore_derived);
    }
}

// Is `key` one that decode adds beside field f (its physical value, flag bits, payload text)?
template <class M>
bool derived_key(std::string_view key) {
    const auto& keys = keys_of<M>();
    for (const auto& k : keys) {
        for (PyObject* s : {k.physical, k.bits}) {
            Py_ssize_t n = 0;
            const char* c = PyUnicode_AsUTF8AndSize(s, &n);
            if (c && key == std::string_view(c, static_cast<std::size_t>(n))) return true;
        }
        Py_ssize_t n = 0;
        const char* c = PyUnicode_AsUTF8AndSize(k.name, &n);
        if (c && key == std::string(c, static_cast<std::size_t>(n)) + "_text") return true;
    }
    return false;
}

template <class M>
std::string field_names() {
    std::string names;
    robowire::for_each_field<M>([&](const auto& f) { names += (names.empty() ? "" : ", ") + std::string(f.name); });
    return names.empty() ? "none" : names;
}

// Sets M's fields from the dict's entries; fields not given keep M's defaults.
template <class Top, class M>
void fill(M& m, PyObject* dict, std::size_t base, const path* parent, bool ignore_derived) {
    PyObject *key = nullptr, *value = nullptr;
    Py_ssize_t pos = 0;
    while (PyDict_Next(dict, &pos, &key, &value)) {
        if (!PyUnicode_Check(key)) throw py::type_error(parent->str() + ": field names are str, got " + type_name(key));
        const std::string key_text = name_of(key);
        const std::string_view name(key_text);
        bool found = false;
        robowire::for_each_field<M>([&](const auto& f) {
            using F = std::remove_cvref_t<decltype(f)>;
            if (found || f.name != name) return;
            found = true;
            auto& member = m.*(f.member);
            const path at{parent, f.name};
            if constexpr (F::is_optional) {
                if (value == Py_None) member.reset();
                else read_field<Top>(f, member.emplace(), value, base, at, ignore_derived);
            } else {
                read_field<Top>(f, member, value, base, at, ignore_derived);
            }
        });
        if (found) continue;
        if (ignore_derived && derived_key<M>(name)) continue;
        std::string what = "unknown field " + parent->str() + "." + shorten(std::string(name)) + " (fields of " + std::string(robowire::table_v<M>.name) +
                           ": " + field_names<M>() + ")";
        if (!ignore_derived && derived_key<M>(name)) what += "; decode adds it beside the raw value, encode takes the raw value";
        throw py::key_error(what);
    }
}

// Encodes message M from a dict of fields.
template <class M>
py::bytes encode_fields(PyObject* fields, bool ignore_derived) {
    M m{};
    const path root{nullptr, robowire::table_v<M>.name};
    if (fields) fill<M>(m, fields, 0, &root, ignore_derived);
    const auto r = robowire::encode(m);
    if (!r) raise_for<M>(classes().encode, r.error());
    return py::bytes(reinterpret_cast<const char*>(r->data()), r->size());
}

// ---------------------------------------------------------------- variants
using robowire::for_each_alternative;

// Encodes the alternative of V named `name`; false when V has none.
template <class V>
bool encode_named(std::string_view name, PyObject* fields, bool ignore_derived, py::bytes& out) {
    bool done = false;
    for_each_alternative<V>([&](auto t) {
        using M = typename decltype(t)::type;
        if (done || robowire::table_v<M>.name != name) return;
        done = true;
        out = encode_fields<M>(fields, ignore_derived);
    });
    return done;
}

template <class V>
std::string message_names() {
    std::string s;
    for_each_alternative<V>([&](auto t) {
        s += (s.empty() ? "" : ", ") + std::string(robowire::table_v<typename decltype(t)::type>.name);
    });
    return s;
}

// Raises DecodeError for a decode error with `text`, the protocol's
// describe_error line for it ("status: input too short (54 or 68..129
// bytes) at byte 4"); .message and .field are the names the line starts
// with ("message.field: ..." or "message: ..."), None when it names none.
[[noreturn]] inline void raise_decode(std::string_view text, const robowire::error& e, const std::vector<std::string>& notes = {}) {
    std::string_view message, field;
    const auto colon = text.find(": ");
    if (colon != std::string_view::npos && text.substr(0, colon).find(' ') == std::string_view::npos) {
        message = text.substr(0, colon);
        if (const auto dot = message.find('.'); dot != std::string_view::npos) {
            field = message.substr(dot + 1);
            message = message.substr(0, dot);
        }
    }
    raise(classes().decode, text, e.code, e.offset, field, message, notes);
}

// The bytes of a bytes-like object (bytes, bytearray, memoryview, ...).
inline std::span<const std::uint8_t> view_of(PyObject* o, Py_buffer& view) {
    if (PyBytes_Check(o))
        return {reinterpret_cast<const std::uint8_t*>(PyBytes_AS_STRING(o)), static_cast<std::size_t>(PyBytes_GET_SIZE(o))};
    if (!PyObject_CheckBuffer(o) || PyUnicode_Check(o))
        throw py::type_error(std::string("expected bytes, bytearray or memoryview, got ") + type_name(o) +
                             (PyUnicode_Check(o) ? " (hex text: bytes.fromhex(text))" : ""));
    if (PyObject_GetBuffer(o, &view, PyBUF_SIMPLE) != 0) throw py::error_already_set();
    return {static_cast<const std::uint8_t*>(view.buf), static_cast<std::size_t>(view.len)};
}
// Holds a buffer for the duration of a call.
class byte_input {
public:
    explicit byte_input(py::handle o) { bytes_ = view_of(o.ptr(), view_); }
    ~byte_input() {
        if (view_.obj) PyBuffer_Release(&view_);
    }
    byte_input(const byte_input&) = delete;
    byte_input& operator=(const byte_input&) = delete;
    std::span<const std::uint8_t> span() const { return bytes_; }

private:
    Py_buffer view_{};
    std::span<const std::uint8_t> bytes_;
};

// decode(data, direction=None) and encode(message, **fields) take *args and
// **kwargs and match them here: pybind11 refuses a call that matches no
// signature with a TypeError it formats from the keywords, and aborts the
// interpreter on a keyword that is not UTF-8 (the other functions are
// guarded in Python, robowire/_errors.py; these two are the hot paths).
template <class Fn>
auto decode_entry(Fn fn) {
    return [fn](const py::args& a, const py::kwargs& k) {
        if (a.size() > 2)
            throw py::type_error("decode() takes data and direction, " + std::to_string(a.size()) + " positional arguments given");
        py::object data, dir = py::none();
        if (a.size() >= 1) data = a[0];
        if (a.size() == 2) dir = a[1];
        for (auto item : k) {
            const std::string key = name_of(item.first.ptr());
            if (key == "data" && !data) data = py::reinterpret_borrow<py::object>(item.second);
            else if (key == "direction" && a.size() < 2) dir = py::reinterpret_borrow<py::object>(item.second);
            else throw py::type_error("decode() got an unexpected keyword argument " + shorten(py::repr(item.first).cast<std::string>()));
        }
        if (!data) throw py::type_error("decode() missing its data (bytes)");
        return fn(data, dir);
    };
}
template <class Fn>
auto encode_entry(Fn fn) {
    return [fn](const py::args& a, py::kwargs k) {
        if (a.size() != 1)
            throw py::type_error("encode() takes a message (a name or a dict as decode returns it) and fields as keywords, " +
                                 std::to_string(a.size()) + " positional arguments given");
        return fn(a[0], k);
    };
}

// encode(message, **fields) or encode(dict): which message and which fields.
struct encode_request {
    std::string name;
    PyObject* fields = nullptr;  // borrowed; may be null
    bool from_dict = false;
};
inline encode_request encode_args(std::string_view protocol, py::handle message, py::handle kwargs) {
    encode_request r;
    if (PyUnicode_Check(message.ptr())) {
        r.name = name_of(message.ptr());
        r.fields = kwargs && !kwargs.is_none() && PyDict_Size(kwargs.ptr()) > 0 ? kwargs.ptr() : nullptr;
        return r;
    }
    if (!PyDict_Check(message.ptr()))
        throw py::type_error("encode: expected a message name (str) or a dict as decode returns it, got " + type_name(message.ptr()));
    if (kwargs && !kwargs.is_none() && PyDict_Size(kwargs.ptr()) > 0)
        throw py::type_error("encode: give a dict or a message name with fields, not both");
    PyObject* d = message.ptr();
    PyObject* name = PyDict_GetItemString(d, "message");
    if (!name) throw py::key_error("encode: the dict has no \"message\"");
    if (!PyUnicode_Check(name)) throw py::type_error("encode: \"message\" is not a str");
    r.name = name_of(name);
    if (PyObject* p = PyDict_GetItemString(d, "protocol"); p && PyUnicode_Check(p)) {
        const auto given = name_of(p);
        if (given != protocol) throw py::value_error("encode: a " + given + " message given to " + std::string(protocol) + ".encode");
    }
    PyObject* fields = PyDict_GetItemString(d, "fields");
    if (fields && fields != Py_None && !PyDict_Check(fields)) throw py::type_error("encode: \"fields\" is not a dict");
    r.fields = fields == Py_None ? nullptr : fields;
    r.from_dict = true;
    return r;
}

}  // namespace rwpy
