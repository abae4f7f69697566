#include "codec/codec_list.h"

namespace octaclay::core {

const std::vector<Codec>& codecs() {
  static const std::vector<Codec> all = [] {
    std::vector<Codec> list{makeBytepackCodec(), makeDctCodec(), makeExrCodec(), makeWaveletCodec(),
                            makeLosslessCodec()};
    return list;
  }();
  return all;
}

const Codec* findCodec(std::string_view id) {
  for (const Codec& c : codecs())
    if (c.info.id == id) return &c;
  return nullptr;
}

const Codec* findCodec(std::uint8_t code) {
  for (const Codec& c : codecs())
    if (c.info.code == code) return &c;
  return nullptr;
}

} // namespace octaclay::core
