#include "octaclay/core/document/scene_io.h"

#include "detail/exr_memory_stream.h"
#include "detail/exr_sink_stream.h"
#include "detail/parallel_rows.h"
#include "document_parts.h"
#include "exr_part_scan.h"
#include "raw_exr_lines.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"

#include <ImfInputFile.h>
#include <ImfInputPart.h>
#include <ImfIntAttribute.h>
#include <ImfMultiPartInputFile.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>

#include <algorithm>
#include <exception>
#include <memory>
#include <mutex>
#include <new>
#include <set>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {
using detail::kHeightAttribute, detail::kParameterizationAttribute, detail::kTopologyAttribute,
    detail::kWidthAttribute;

constexpr const char* kNameAttribute = "octaclay.name";
constexpr const char* kTranslationAttribute = "octaclay.translation";
constexpr const char* kRotationAttribute = "octaclay.rotation"; // Euler XYZ, degrees
constexpr const char* kScaleAttribute = "octaclay.scale";
constexpr const char* kVisibleAttribute = "octaclay.visible";
constexpr const char* kLockedAttribute = "octaclay.locked";

[[noreturn]] void refuse(const fs::path& path, const std::string& why) {
  throw Error(ErrorKind::InvalidInput, path.string() + ": " + why);
}

Imath::V3f toImath(Vec3f v) {
  return {v.x, v.y, v.z};
}
Vec3f fromImath(const Imath::V3f& v) {
  return {v.x, v.y, v.z};
}

void addObjectAttributes(Imf::Header& header, const SceneObject& object) {
  header.insert(kNameAttribute, Imf::StringAttribute(object.name));
  // In cells, as document_io writes them for a torus or plane: (width+1)×(height+1) samples.
  header.insert(kWidthAttribute, Imf::IntAttribute(object.document.positions.width()));
  header.insert(kHeightAttribute, Imf::IntAttribute(object.document.positions.height()));
  header.insert(kTranslationAttribute, Imf::V3fAttribute(toImath(object.transform.translation)));
  header.insert(kRotationAttribute, Imf::V3fAttribute(toImath(object.transform.rotationDegrees)));
  header.insert(kScaleAttribute, Imf::V3fAttribute(toImath(object.transform.scale)));
  header.insert(kVisibleAttribute, Imf::IntAttribute(object.visible ? 1 : 0));
  header.insert(kLockedAttribute, Imf::IntAttribute(object.locked ? 1 : 0));
}

std::string defaultName(const fs::path& path) {
  const std::string stem = path.stem().string();
  return objectNameProblem(stem) ? "Model" : stem;
}

// A flag attribute: absent → fallback; 0 or 1; anything else is a lie.
bool flag(const fs::path& path, const Imf::Header& header, const char* attribute, bool fallback,
          const std::string& part) {
  const auto* value = header.findTypedAttribute<Imf::IntAttribute>(attribute);
  if (!value) {
    if (header.find(attribute) != header.end())
      refuse(path, part + ": " + attribute + " is not an int attribute");
    return fallback;
  }
  if (value->value() != 0 && value->value() != 1)
    refuse(path, part + ": " + attribute + " is " + std::to_string(value->value()) +
                     " (0 or 1 expected)");
  return value->value() == 1;
}

Vec3f vector(const fs::path& path, const Imf::Header& header, const char* attribute, Vec3f fallback,
             const std::string& part) {
  const auto* value = header.findTypedAttribute<Imf::V3fAttribute>(attribute);
  if (!value) {
    if (header.find(attribute) != header.end())
      refuse(path, part + ": " + attribute + " is not a v3f attribute");
    return fallback;
  }
  return fromImath(value->value());
}

// The object a part's header describes, every scene attribute checked, the document header
// checked last (its messages are readDocumentHeader's). index counts from 0; fallbackName is
// the name of an object whose header names none.
SceneObjectHeader describePart(const fs::path& path, const Imf::Header& header, std::size_t index,
                               const std::string& fallbackName) {
  SceneObjectHeader object;
  const auto* name = header.findTypedAttribute<Imf::StringAttribute>(kNameAttribute);
  object.name = name ? name->value() : fallbackName;
  const std::string part = "object " + std::to_string(index + 1) + " ('" + object.name + "')";
  if (const auto problem = objectNameProblem(object.name)) refuse(path, part + ": " + *problem);

  for (const char* attribute : {kParameterizationAttribute, kTopologyAttribute})
    if (const auto* named = header.findTypedAttribute<Imf::StringAttribute>(attribute))
      if (!parseTopology(named->value()))
        refuse(path,
               part + ": unknown topology '" + named->value() + "' (octahedral, torus or plane)");

  // In cells: the data window holds one sample more each way.
  const Imath::Box2i window = header.dataWindow();
  const long long columns = static_cast<long long>(window.max.x) - window.min.x;
  const long long rows = static_cast<long long>(window.max.y) - window.min.y;
  for (const auto& [attribute, declared] :
       {std::pair{kWidthAttribute, columns}, std::pair{kHeightAttribute, rows}}) {
    const auto* value = header.findTypedAttribute<Imf::IntAttribute>(attribute);
    if (value && value->value() != declared)
      refuse(path, part + ": its header says " + attribute + " = " +
                       std::to_string(value->value()) + " but its image is " +
                       std::to_string(columns + 1) + "x" + std::to_string(rows + 1) + " samples (" +
                       std::to_string(columns) + "x" + std::to_string(rows) + " cells)");
  }

  object.transform.translation = vector(path, header, kTranslationAttribute, {}, part);
  object.transform.rotationDegrees = vector(path, header, kRotationAttribute, {}, part);
  object.transform.scale = vector(path, header, kScaleAttribute, {1, 1, 1}, part);
  if (const auto problem = transformProblem(object.transform)) refuse(path, part + ": " + *problem);
  object.visible = flag(path, header, kVisibleAttribute, true, part);
  object.locked = flag(path, header, kLockedAttribute, false, part);

  object.document = detail::checkDocumentHeader(path, header);
  object.topology = object.document.topology;
  object.width = object.document.width;
  object.height = object.document.height;
  return object;
}

// Names unique, format versions equal: what the parts must agree on.
void checkPartsAgree(const fs::path& path, const std::vector<SceneObjectHeader>& objects) {
  std::set<std::string_view> names;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    if (!names.insert(objects[k].name).second)
      refuse(path, "objects " + std::to_string(k + 1) + " and another are both named '" +
                       objects[k].name + "' (names are unique)");
    if (objects[k].document.formatVersion != objects[0].document.formatVersion)
      refuse(path, "the parts disagree: object " + std::to_string(k + 1) + " is format version " +
                       std::to_string(objects[k].document.formatVersion) + ", object 1 version " +
                       std::to_string(objects[0].document.formatVersion));
  }
}

detail::ExrFileOutline scanned(const fs::path& path) {
  detail::requireExrMagic(path);
  return detail::scanExrHeaders(path, kMaxSceneObjects);
}

template <typename Body> auto guarded(const fs::path& path, Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    refuse(path, "not enough memory to read it: the document is larger than this machine can "
                 "hold");
  } catch (const std::exception& e) {
    refuse(path, std::string("corrupt or truncated OpenEXR data: ") + e.what());
  }
}

std::vector<SceneObjectHeader> multiPartHeaders(const fs::path& path,
                                                const Imf::MultiPartInputFile& file) {
  std::vector<SceneObjectHeader> objects;
  objects.reserve(static_cast<std::size_t>(file.parts()));
  for (int k = 0; k < file.parts(); ++k) {
    const Imf::Header& header = file.header(k);
    objects.push_back(describePart(path, header, static_cast<std::size_t>(k),
                                   header.hasName() ? header.name() : "Object"));
  }
  checkPartsAgree(path, objects);
  return objects;
}

} // namespace

std::vector<SceneObjectHeader> readSceneHeaders(const fs::path& path) {
  const detail::ExrFileOutline outline = scanned(path);
  return guarded(path, [&] {
    if (!outline.multiPart) {
      Imf::InputFile file(path.c_str());
      return std::vector<SceneObjectHeader>{
          describePart(path, file.header(), 0, defaultName(path))};
    }
    Imf::MultiPartInputFile file(path.c_str(), 1);
    return multiPartHeaders(path, file);
  });
}

Scene readScene(const fs::path& path, const DocumentReadOptions& options) {
  const detail::ExrFileOutline outline = scanned(path);
  Scene scene;
  if (!outline.multiPart) {
    SceneObjectHeader described;
    Document document =
        detail::readDocumentInspecting(path, options, [&](const Imf::Header& header) {
          described = describePart(path, header, 0, defaultName(path));
        });
    scene.objects.push_back({described.name, std::move(document), described.transform,
                             described.visible, described.locked});
    scene.objects.back().document.topology = described.topology;
    return scene;
  }
  guarded(path, [&] {
    Imf::MultiPartInputFile file(path.c_str(), detail::exrThreads());
    const std::vector<SceneObjectHeader> objects = multiPartHeaders(path, file);
    for (int k = 0; k < file.parts(); ++k)
      if (!file.partComplete(k))
        refuse(path, "truncated: the file ends before all the pixels of object " +
                         std::to_string(k + 1) + " ('" + objects[k].name +
                         "') (an interrupted copy?)");
    // Every part at once, each on one core: raw_exr_lines reads a part's lines straight from
    // the file; OpenEXR reads compressed parts, each core with a file of its own and no pool
    // (one file's parts share its stream's lock, and its pool's hand-offs per scan line cost
    // more than a small part's decoding: 16 parts of N = 256 read 1.5x slower per sample than
    // one object through it). Nested, a part's rows run serially: the parts cost what one
    // object of their samples costs, not one fork and join each.
    std::vector<Document> documents(objects.size());
    std::vector<std::exception_ptr> errors(objects.size());
    std::mutex shared; // the one file's parts, when bands share it
    const auto readPart = [&](int k, Imf::MultiPartInputFile& from) {
      const SceneObjectHeader& described = objects[static_cast<std::size_t>(k)];
      documents[static_cast<std::size_t>(k)] = detail::readDocumentPixels(
          path, file.header(k), described.document, options,
          [&](const Imf::FrameBuffer& frame, int first, int last) {
            std::unique_lock lock(shared, std::defer_lock);
            if (&from == &file) lock.lock();
            Imf::InputPart part(from, k);
            part.setFrameBuffer(frame);
            part.readPixels(first, last);
          },
          k);
      documents[static_cast<std::size_t>(k)].topology = described.topology;
    };
    bool raw = true;
    for (int k = 0; k < file.parts(); ++k)
      raw = raw && detail::rawLinesApply(file.header(k));
    detail::parallelRows(
        file.parts(),
        [&](int begin, int end) {
          std::unique_ptr<Imf::MultiPartInputFile> own;
          for (int k = begin; k < end; ++k)
            try {
              if (!raw && !own && end - begin < file.parts())
                own = std::make_unique<Imf::MultiPartInputFile>(path.c_str(), 0);
              readPart(k, own ? *own : file);
            } catch (...) {
              errors[static_cast<std::size_t>(k)] = std::current_exception();
            }
        },
        1);
    for (const std::exception_ptr& error : errors) // the first object's problem, as read in turn
      if (error) std::rethrow_exception(error);
    scene.objects.reserve(objects.size());
    for (std::size_t k = 0; k < objects.size(); ++k)
      scene.objects.push_back({objects[k].name, std::move(documents[k]), objects[k].transform,
                               objects[k].visible, objects[k].locked});
  });
  return scene;
}

void writeScene(const Scene& scene, const fs::path& path, const DocumentWriteOptions& options) {
  if (const auto problem = sceneProblem(scene))
    throw Error(ErrorKind::InvalidArgument, "cannot write " + path.string() + ": " + *problem);
  if (scene.objects.size() == 1) {
    const SceneObject& object = scene.objects.front();
    detail::writeDocumentWithAttributes(object.document, path, options, [&](Imf::Header& header) {
      addObjectAttributes(header, object);
    });
    return;
  }
  std::vector<Imf::Header> headers;
  headers.reserve(scene.objects.size());
  for (const SceneObject& object : scene.objects) {
    headers.push_back(detail::documentPartHeader(object.document, options));
    addObjectAttributes(headers.back(), object);
    headers.back().setName(object.name);
    headers.back().setType(Imf::SCANLINEIMAGE);
  }
  if (std::all_of(headers.begin(), headers.end(),
                  [](const Imf::Header& header) { return detail::rawLinesApply(header); })) {
    // OpenEXR writes the headers and the offset tables' places into memory; every part's lines
    // are made on every core and written at their places (raw_exr_lines), as for one object.
    detail::ExrMemoryStream head;
    {
      Imf::MultiPartOutputFile file(head, headers.data(), static_cast<int>(headers.size()), true,
                                    1);
    }
    std::vector<detail::RawPart> parts;
    parts.reserve(scene.objects.size());
    for (std::size_t k = 0; k < scene.objects.size(); ++k)
      parts.push_back({scene.objects[k].document, headers[k]});
    writeFileAtomically(
        path, [&](ByteSink& sink) { detail::writeRawParts(parts, true, head.bytes(), sink); });
    return;
  }
  writeFileAtomically(path, [&](ByteSink& sink) {
    detail::ExrSinkStream stream(sink);
    {
      // The display window is a shared attribute of a multi-part file: parts of other sizes
      // take the first part's (overrideSharedAttributes); each part's data window is its own.
      Imf::MultiPartOutputFile file(stream, headers.data(), static_cast<int>(headers.size()), true,
                                    detail::exrThreads());
      for (std::size_t k = 0; k < scene.objects.size(); ++k) {
        Imf::OutputPart part(file, static_cast<int>(k));
        detail::writeDocumentPixels(scene.objects[k].document, headers[k],
                                    [&](const Imf::FrameBuffer& frame, int rows) {
                                      part.setFrameBuffer(frame);
                                      part.writePixels(rows);
                                    });
      }
    }
    stream.finish();
  });
}

} // namespace octaclay::core
