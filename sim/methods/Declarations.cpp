// The building blocks of a method's declaration.
#include "sim/methods/Declarations.h"

namespace prisca::sim::methods {

// ---- The parameters methods are tuned by (MethodParameter): declared once, here. -------------
Eigen::VectorXd one(double v) {
    return Eigen::VectorXd::Constant(1, v);
}

MethodParameter integer(const char* name, const char* label, const char* unit, double low,
                        double high, const char* help) {
    MethodParameter p;
    p.name = name;
    p.label = label;
    p.unit = unit;
    p.kind = Kind::Integer;
    p.minimum = low;
    p.maximum = high;
    p.decimals = 0;
    p.help = help;
    return p;
}

MethodParameter real(const char* name, const char* label, const char* unit, double low, double high,
                     int decimals, const char* help) {
    MethodParameter p = integer(name, label, unit, low, high, help);
    p.kind = Kind::Real;
    p.decimals = decimals;
    return p;
}

MethodParameter onOff(const char* name, const char* label, const char* help) {
    MethodParameter p = integer(name, label, "", 0, 1, help);
    p.kind = Kind::Switch;
    return p;
}

MethodSpec entry(const char* id, const char* label, MethodSpec::Create create) {
    MethodSpec s;
    s.id = QString::fromLatin1(id);
    s.label = QString::fromUtf8(label);
    s.create = create;
    return s;
}

}  // namespace prisca::sim::methods
