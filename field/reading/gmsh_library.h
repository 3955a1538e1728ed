#pragma once
// Gmsh's library (libgmsh4.8) opened at run time, not linked, for the .msh
// reader (field/reading/gmsh_reading.cpp): linked, its 90 more shared
// libraries (OpenCASCADE, FLTK, X11) loaded into every process of hsb
// (`hsb --version` took 0.16 s and 74 MB, against 0.03 s and 37 MB
// without); opened, only the child process that parses a .msh pays (0.09
// s). Its C API (gmshc.h, for its functions' types only): functions dlsym
// finds by name, each giving an error in its last argument (its message
// kept by Gmsh's logger), the arrays they return Gmsh's own, freed by
// gmshFree. Internal to field/reading/.

#include <dlfcn.h>
extern "C" {
#include <gmshc.h>
}

#include <cstddef>
#include <string>

#include "field/reading/data_error.h"

namespace hsb {

// The soname of the library whose API gmshc.h declares (libgmsh4.8's).
static_assert(GMSH_API_VERSION_MAJOR == 4 && GMSH_API_VERSION_MINOR == 8, "gmshc.h is not Gmsh 4.8's: name its soname");
inline constexpr const char* gmsh_soname = "libgmsh.so.4.8";

// The address of a function of the library, converted to its type.
struct GmshSymbol {
  void* address;
  template <class Function>
  operator Function*() const { return reinterpret_cast<Function*>(address); }
};

// The functions of Gmsh's C API read here, found in `library` (null where
// it lacks one: `missing` names it).
struct GmshApi {
  void* library = nullptr;
  std::string missing;
  GmshSymbol find(const char* name) {
    void* address = library ? dlsym(library, name) : nullptr;
    if (library && !address && missing.empty()) missing = name;
    return {address};
  }
  decltype(&gmshInitialize) initialize = find("gmshInitialize");
  decltype(&gmshFinalize) finalize = find("gmshFinalize");
  decltype(&gmshOptionSetNumber) set_number = find("gmshOptionSetNumber");
  decltype(&gmshOptionGetNumber) get_number = find("gmshOptionGetNumber");
  decltype(&gmshOptionGetString) get_string = find("gmshOptionGetString");
  decltype(&gmshOpen) open = find("gmshOpen");
  decltype(&gmshModelMeshGetNodes) nodes = find("gmshModelMeshGetNodes");
  decltype(&gmshModelMeshGetElements) elements = find("gmshModelMeshGetElements");
  decltype(&gmshModelMeshGetElementProperties) element_properties = find("gmshModelMeshGetElementProperties");
  decltype(&gmshViewGetTags) view_tags = find("gmshViewGetTags");
  decltype(&gmshViewGetIndex) view_index = find("gmshViewGetIndex");
  decltype(&gmshViewGetModelData) model_data = find("gmshViewGetModelData");
  decltype(&gmshLoggerGetLastError) last_error = find("gmshLoggerGetLastError");
  decltype(&gmshFree) free = find("gmshFree");
};
inline GmshApi gmsh;  // loaded by the first read, never closed (its destructors run at the exit)

inline void load_gmsh(const std::string& path) {
  if (gmsh.library) return;
  GmshApi api{dlopen(gmsh_soname, RTLD_NOW | RTLD_LOCAL)};
  const char* why = api.library ? nullptr : dlerror();
  if (why || !api.missing.empty())
    throw DataError(path + ": reading .msh needs Gmsh's library (Debian: libgmsh4.8), which cannot be loaded: " +
                    (why ? why : gmsh_soname + std::string(" has no ") + api.missing));
  gmsh = api;
}

// `length` values Gmsh allocated at `data`.
template <class T>
struct GmshValues {
  T* data = nullptr;
  std::size_t length = 0;
  std::size_t size() const { return length; }
  bool empty() const { return length == 0; }
  const T& operator[](std::size_t i) const { return data[i]; }
  const T* begin() const { return data; }
  const T* end() const { return data + length; }
};

// An array Gmsh returns, freed at the end of scope.
template <class T>
struct GmshArray : GmshValues<T> {
  GmshArray() = default;
  GmshArray(const GmshArray&) = delete;
  GmshArray& operator=(const GmshArray&) = delete;
  ~GmshArray() { gmsh.free(this->data); }
};

// Arrays Gmsh returns in one (by element type, by entity), all freed at
// the end of scope.
template <class T>
struct GmshArrays {
  T** data = nullptr;
  std::size_t* lengths = nullptr;
  std::size_t count = 0;
  GmshArrays() = default;
  GmshArrays(const GmshArrays&) = delete;
  GmshArrays& operator=(const GmshArrays&) = delete;
  ~GmshArrays() {
    for (std::size_t i = 0; data && i < count; ++i) gmsh.free(data[i]);
    gmsh.free(data);
    gmsh.free(lengths);
  }
  std::size_t size() const { return count; }
  GmshValues<T> operator[](std::size_t i) const { return {data[i], lengths[i]}; }
};

// A string Gmsh returns, copied and freed.
inline std::string taken(char* text) {
  const std::string copy = text ? text : "";
  gmsh.free(text);
  return copy;
}

// An error a call of Gmsh's gave in `error` (an exception in Gmsh, or an
// allocation a corrupt count made fail, which its C API catches) as a
// DataError naming the file, saying Gmsh's last error message.
inline void refuse_gmsh_error(const std::string& path, int error) {
  if (error == 0) return;
  char* message = nullptr;
  int ignored = 0;
  gmsh.last_error(&message, &ignored);
  const std::string said = taken(message);
  throw DataError(path + ": Gmsh cannot read it: " +
                  (said.empty() ? "it gives no reason (a corrupt count may ask for more memory than there is)" : said));
}

// Calls Gmsh's `function` with `arguments` and its error argument.
template <class Function, class... Arguments>
void gmsh_call(const std::string& path, Function function, Arguments... arguments) {
  int error = 0;
  function(arguments..., &error);
  refuse_gmsh_error(path, error);
}

}  // namespace hsb
