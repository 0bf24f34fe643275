#pragma once
// The mutation tests' view of a certificate: its text parsed into vertices, faces, cells
// and claims (Cert), and written back (serialize), so mutations can edit one entity.
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "dualhex/topology/lattice.hpp"

namespace dualhex {
namespace {

struct Cert {
    std::vector<std::string> head;  // name/kind/domain lines (name is replaced)
    std::vector<LatticePoint> pos;
    std::vector<std::vector<int>> faces;
    std::vector<std::vector<int>> cells;  // 2*f + side
    std::vector<std::string> claims;  // the text after "claim "
    std::string domain;               // "box" / "torus" / "point" (lo)
    std::int64_t lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, period = 0;
};

inline Cert parse(const std::string& text) {
    Cert c;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        std::string key;
        ls >> key;
        if (key == "name" || key == "kind") c.head.push_back(line);
        if (key == "domain") {
            c.head.push_back(line);
            ls >> c.domain;
            if (c.domain == "box") ls >> c.lo[0] >> c.lo[1] >> c.lo[2] >> c.hi[0] >> c.hi[1] >> c.hi[2];
            else if (c.domain == "point") ls >> c.lo[0] >> c.lo[1] >> c.lo[2];
            else ls >> c.period;
        }
        if (key == "v") {
            LatticePoint p;
            ls >> p.x >> p.y >> p.z;
            c.pos.push_back(p);
        }
        if (key == "f") {
            std::vector<int> f;
            for (int v; ls >> v;) f.push_back(v);
            c.faces.push_back(f);
        }
        if (key == "c") {
            std::vector<int> k;
            for (std::string t; ls >> t;) k.push_back(2 * std::stoi(t.substr(1)) + (t[0] == '-'));
            c.cells.push_back(k);
        }
        if (key == "claim") c.claims.push_back(line.substr(6));
    }
    return c;
}

inline std::string serialize(const Cert& c, const std::string& name) {
    std::ostringstream o;
    o << "dualhex-certificate 2\n";
    for (const std::string& h : c.head) o << (h.rfind("name ", 0) == 0 ? "name " + name : h) << '\n';
    for (const auto& p : c.pos) o << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& f : c.faces) {
        o << 'f';
        for (int v : f) o << ' ' << v;
        o << '\n';
    }
    for (const auto& k : c.cells) {
        o << 'c';
        for (int h : k) o << ' ' << (h % 2 ? '-' : '+') << h / 2;
        o << '\n';
    }
    for (const auto& cl : c.claims) o << "claim " << cl << '\n';
    o << "end\n";
    return o.str();
}

}  // namespace
}  // namespace dualhex
