#include "render_state.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "core/error.h"

namespace lw::cli {

namespace {

// 2: one tracker per line set; 3: the line mesh's pose; 4: the view scale of the coherent
// parameterization; 5: the paths of a still view (still_paths.h); 6: those written field by
// field, with the key of the settings they were made with; 7: their keys mixed by core's mix64;
// 8: no pose (the line mesh is built at 0 s, whatever frame comes first).
constexpr char kMagic[8] = {'L', 'W', 'S', 'T', 'A', 'T', 'E', '8'};

class Writer {
public:
    template <class T>
    void put(const T& value) {
        put_bytes(&value, sizeof(T));
    }
    void put_bytes(const void* data, size_t size) { bytes.append(static_cast<const char*>(data), size); }
    std::string bytes;
};

class Reader {
public:
    Reader(std::vector<char> bytes, std::string where) : bytes_(std::move(bytes)), where_(std::move(where)) {}
    template <class T>
    T get() {
        T value;
        get_bytes(&value, sizeof(T));
        return value;
    }
    void get_bytes(void* out, size_t size) {
        if (size == 0) return;  // `out` may be an empty vector's null data()
        if (size > bytes_.size() - at_) throw Error(where_ + ": truncated state file");
        std::memcpy(out, bytes_.data() + at_, size);
        at_ += size;
    }
    uint32_t count(size_t item_size) {
        const auto n = get<uint32_t>();
        if (size_t(n) * item_size > bytes_.size() - at_) throw Error(where_ + ": truncated state file");
        return n;
    }

    const std::string& where() const { return where_; }

private:
    std::vector<char> bytes_;
    std::string where_;
    size_t at_ = 0;
};

void put_state(Writer& w, const std::optional<CoherenceTracker::State>& state) {
    w.put<uint8_t>(state ? 1 : 0);
    if (!state) return;
    w.put<uint8_t>(state->has_previous ? 1 : 0);
    w.put(state->camera);
    w.put(state->radius);
    w.put(uint32_t(state->sprites.size()));
    w.put_bytes(state->sprites.data(), state->sprites.size() * sizeof(glm::vec3));
    w.put(state->view_rho);
    // Field by field: the structs have padding, which would put stray bytes in the file.
    w.put(state->still.settings);
    w.put(uint32_t(state->still.paths.size()));
    for (const StillPath& path : state->still.paths) {
        w.put(path.key);
        w.put(path.rotation);
        w.put(path.first_piece);
        w.put(path.pieces);
    }
    w.put(uint32_t(state->still.pieces.size()));
    for (const StillPiece& piece : state->still.pieces) {
        const PathParam& p = piece.param;
        w.put(piece.first);
        w.put(piece.count);
        for (const float v : {p.rho, p.phi, p.fold.level, p.fold.scale, p.fold.w, p.length_px}) w.put(v);
        w.put(p.votes);
        w.put<uint8_t>(p.fitted ? 1 : 0);
    }
}

std::optional<CoherenceTracker::State> get_state(Reader& r) {
    if (r.get<uint8_t>() == 0) return std::nullopt;
    CoherenceTracker::State state;
    state.has_previous = r.get<uint8_t>() != 0;
    state.camera = r.get<CameraMatrices>();
    state.radius = r.get<float>();
    state.sprites.resize(r.count(sizeof(glm::vec3)));
    r.get_bytes(state.sprites.data(), state.sprites.size() * sizeof(glm::vec3));
    state.view_rho = r.get<float>();
    state.still.settings = r.get<uint64_t>();
    state.still.paths.resize(r.count(8 + 3 * 4));
    for (StillPath& path : state.still.paths) {
        path.key = r.get<uint64_t>();
        path.rotation = r.get<uint32_t>();
        path.first_piece = r.get<uint32_t>();
        path.pieces = r.get<uint32_t>();
    }
    state.still.pieces.resize(r.count(2 * 4 + 6 * 4 + 4 + 1));
    for (StillPiece& piece : state.still.pieces) {
        PathParam& p = piece.param;
        piece.first = r.get<uint32_t>();
        piece.count = r.get<uint32_t>();
        for (float* v : {&p.rho, &p.phi, &p.fold.level, &p.fold.scale, &p.fold.w, &p.length_px}) *v = r.get<float>();
        p.votes = r.get<uint32_t>();
        p.fitted = r.get<uint8_t>() != 0;
    }
    for (const StillPath& path : state.still.paths)
        if (size_t(path.first_piece) + path.pieces > state.still.pieces.size())
            throw Error(r.where() + ": corrupt render state (a still path's pieces lie past the record)");
    if (!std::ranges::is_sorted(state.still.paths, {}, &StillPath::key))
        throw Error(r.where() + ": corrupt render state (still paths out of order)");
    return state;
}

}  // namespace

void write_atomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write) {
    const auto temporary = path.parent_path() / (path.stem().string() + ".partial" + path.extension().string());
    std::error_code ec;
    try {
        write(temporary);
    } catch (...) {  // a failed write leaves no half file behind
        std::filesystem::remove(temporary, ec);
        throw;
    }
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        const std::string why = std::filesystem::is_directory(path) ? "a folder has its name" : ec.message();
        std::filesystem::remove(temporary, ec);
        throw Error(path.string() + ": cannot write (" + why + ")");
    }
}

void create_folder(const std::filesystem::path& dir, const std::string& what) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw Error(dir.string() + ": cannot create " + what + " folder" + (ec ? " (" + ec.message() + ")" : ""));
}

void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
    write_atomically(path, [&](const std::filesystem::path& file) {
        std::ofstream out(file, std::ios::binary);
        if (!out || !(out << text) || !out.flush()) throw Error(path.string() + ": cannot write");
    });
}

std::filesystem::path saved_state_path(const std::filesystem::path& dir, int start) {
    char name[40];
    std::snprintf(name, sizeof name, "state_%04d.lwstate", start);
    return dir / name;
}

void write_render_state(const std::filesystem::path& path, const RenderState& state) {
    Writer w;
    w.put_bytes(kMagic, sizeof(kMagic));
    w.put(uint32_t(state.signature.size()));
    w.put_bytes(state.signature.data(), state.signature.size());
    w.put(int32_t(state.frame));
    w.put(uint32_t(state.snapshot.sets.size()));
    for (const auto& set : state.snapshot.sets) put_state(w, set);
    w.put(uint32_t(state.snapshot.layers.size()));
    for (const auto& layer : state.snapshot.layers) put_state(w, layer);
    write_atomically(path, [&](const std::filesystem::path& file) {
        std::ofstream out(file, std::ios::binary);
        if (!out.write(w.bytes.data(), std::streamsize(w.bytes.size())) || !out.flush())
            throw Error(path.string() + ": cannot write the render state");
    });
}

RenderState read_render_state(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw Error(path.string() + ": " + (std::filesystem::is_directory(path, ec) ? "a folder" : "not a regular file") +
                    ", not a render state (a farm's states are its DIR/states/state_NNNN.lwstate files)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": no render state to resume from (the sequence was not started, or by an "
                                         "older linework)");
    Reader r(std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()), path.string());
    char magic[sizeof(kMagic)];
    r.get_bytes(magic, sizeof(magic));
    if (std::memcmp(magic, kMagic, 7) == 0 && magic[7] != kMagic[7])
        throw Error(path.string() + ": a render state of another linework version; remove it to start over");
    if (std::memcmp(magic, kMagic, sizeof(kMagic)) != 0) throw Error(path.string() + ": not a linework render state");
    RenderState state;
    state.signature.resize(r.count(1));
    r.get_bytes(state.signature.data(), state.signature.size());
    state.frame = r.get<int32_t>();
    const uint32_t sets = r.count(1);
    for (uint32_t i = 0; i < sets; ++i) state.snapshot.sets.push_back(get_state(r));
    const uint32_t layers = r.count(1);
    for (uint32_t i = 0; i < layers; ++i) state.snapshot.layers.push_back(get_state(r));
    return state;
}

}  // namespace lw::cli
