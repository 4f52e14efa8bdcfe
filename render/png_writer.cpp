#include "png_writer.h"

#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include "robot_image.h"
#include "svg_writer.h"

namespace rb::render {

namespace {

constexpr int kScreenW = Canvas::kWidth;
constexpr int kScreenH = Canvas::kHeight;

// How pictures are compressed (bench/README.md, "Issue 38", has the measurements that chose
// these). zlib's level 3 is its fastest matcher with a longer chain than level 1: as fast on
// screens, a little smaller. Z_RLE was faster still on plain screens but 70 times larger on a
// patterned one, and level 6 (libpng's default) took 3 to 4 times as long.
constexpr int kPaletteLevel = 3;
constexpr int kRgbLevel = 3;

}  // namespace

RgbImage screenImage(const Pixels& pixels, int scale) {
  scale = std::clamp(scale, 1, kMaxScale);
  RgbImage image;
  image.width = kScreenW * scale;
  image.height = kScreenH * scale;
  image.rgb.assign(static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 3, 0);
  if (pixels.size() < static_cast<size_t>(kScreenW) * kScreenH) return image;
  const size_t rowBytes = static_cast<size_t>(image.width) * 3;
  for (int y = 0; y < kScreenH; ++y) {
    const Colour* src = pixels.data() + static_cast<size_t>(y) * kScreenW;
    uint8_t* dst = image.rgb.data() + static_cast<size_t>(y) * static_cast<size_t>(scale) * rowBytes;
    // Screens are long runs of one colour: convert a colour number only when it changes.
    Colour last = src[0];
    uint32_t rgb = colourToRgb(last);
    uint8_t* p = dst;
    for (int x = 0; x < kScreenW; ++x) {
      if (src[x] != last) {
        last = src[x];
        rgb = colourToRgb(last);
      }
      for (int k = 0; k < scale; ++k) {
        *p++ = static_cast<uint8_t>(rgb >> 16);
        *p++ = static_cast<uint8_t>(rgb >> 8);
        *p++ = static_cast<uint8_t>(rgb);
      }
    }
    // The other rows of the scaled row are copies of the first.
    for (int k = 1; k < scale; ++k) std::memcpy(dst + static_cast<size_t>(k) * rowBytes, dst, rowBytes);
  }
  return image;
}

void drawRobot(RgbImage& image, const RobotView& robot, int scale) {
  const RobotImage shape(robot);
  if (shape.empty()) return;
  const uint32_t colour = colourToRgb(robot.colour);
  shape.rasterize(std::clamp(scale, 1, kMaxScale), image.width, image.height,
                  [&](int x, int y) { image.set(x, y, colour); });
}

RgbImage composeImage(const Pixels& pixels, const RobotView& robot, int scale) {
  RgbImage image = screenImage(pixels, scale);
  drawRobot(image, robot, scale);
  return image;
}

std::vector<ColourRun> composeRuns(const Pixels& pixels, const RobotView& robot) {
  std::vector<ColourRun> runs;
  if (pixels.size() < static_cast<size_t>(kScreenW) * kScreenH) return runs;
  // The robot's pixels, row by row: they replace the screen's.
  std::vector<std::pair<int, int>> dots;  // (y, x)
  const RobotImage shape(robot);
  if (!shape.empty())
    shape.rasterize(1, kScreenW, kScreenH, [&](int x, int y) { dots.push_back({y, x}); });
  std::sort(dots.begin(), dots.end());
  dots.erase(std::unique(dots.begin(), dots.end()), dots.end());
  const uint32_t robotRgb = colourToRgb(robot.colour);
  auto push = [&runs](uint32_t rgb, uint32_t n) {
    if (!runs.empty() && runs.back().rgb == rgb) runs.back().count += n;
    else runs.push_back({n, rgb});
  };
  size_t d = 0;
  for (int y = 0; y < kScreenH; ++y) {
    const Colour* row = pixels.data() + static_cast<size_t>(y) * kScreenW;
    int x = 0;
    while (x < kScreenW) {
      int robotX = d < dots.size() && dots[d].first == y ? dots[d].second : kScreenW;
      while (x < robotX) {
        Colour c = row[x];
        int end = x + 1;
        while (end < robotX && row[end] == c) ++end;
        push(colourToRgb(c), static_cast<uint32_t>(end - x));
        x = end;
      }
      if (robotX < kScreenW) {
        push(robotRgb, 1);
        x = robotX + 1;
        ++d;
      }
    }
  }
  return runs;
}

RgbImage imageFromRuns(const std::vector<ColourRun>& runs, int width, int height) {
  RgbImage image;
  image.width = width;
  image.height = height;
  image.rgb.assign(static_cast<size_t>(width) * static_cast<size_t>(height) * 3, 0);
  uint8_t* p = image.rgb.data();
  uint8_t* end = p + image.rgb.size();
  for (const ColourRun& r : runs) {
    const uint8_t b0 = static_cast<uint8_t>(r.rgb >> 16), b1 = static_cast<uint8_t>(r.rgb >> 8),
                  b2 = static_cast<uint8_t>(r.rgb);
    size_t n = std::min<size_t>(r.count, static_cast<size_t>(end - p) / 3);
    if (b0 == b1 && b1 == b2) {  // grey, white, black: one memset
      std::memset(p, b0, n * 3);
      p += n * 3;
      continue;
    }
    for (size_t i = 0; i < n; ++i) {
      *p++ = b0;
      *p++ = b1;
      *p++ = b2;
    }
  }
  return image;
}

namespace {

/// What one PNG is written from: plain data only, since libpng reports errors with longjmp,
/// which must not cross anything with a destructor.
struct PngJob {
  int width = 0, height = 0;
  int bitDepth = 8;
  int colourType = PNG_COLOR_TYPE_RGB;
  const png_color* palette = nullptr;
  int paletteSize = 0;
  const uint8_t* rows = nullptr;  ///< height rows of `stride` bytes
  size_t stride = 0;
  int filters = PNG_FILTER_NONE;
  int level = 6;
  int strategy = Z_DEFAULT_STRATEGY;
  std::vector<uint8_t>* out = nullptr;
  const char* error = nullptr;  ///< why it failed
};

void pngError(png_structp png, png_const_charp message) {
  auto* job = static_cast<PngJob*>(png_get_error_ptr(png));
  job->error = message && std::strstr(message, "memory") ? "out of memory" : "libpng failed";
  png_longjmp(png, 1);
}
void pngWarning(png_structp, png_const_charp) {}

void pngWrite(png_structp png, png_bytep data, size_t size) {
  auto* job = static_cast<PngJob*>(png_get_io_ptr(png));
  bool grown = true;
  try {
    job->out->insert(job->out->end(), data, data + size);
  } catch (const std::bad_alloc&) {
    grown = false;
  }
  if (!grown) png_error(png, "out of memory");
}
void pngFlush(png_structp) {}

/// Writes the job's PNG into *job.out; false (with job.error) when libpng fails.
bool runPngJob(PngJob& job) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &job, pngError, pngWarning);
  if (!png) {
    job.error = "out of memory";
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    job.error = "out of memory";
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &job, pngWrite, pngFlush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(job.width), static_cast<png_uint_32>(job.height), job.bitDepth,
               job.colourType, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (job.palette) {
    png_set_PLTE(png, info, job.palette, job.paletteSize);
    png_set_check_for_invalid_index(png, 0);  // every index is one of the palette's, by making
  }
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, job.filters);
  png_set_compression_level(png, job.level);
  png_set_compression_strategy(png, job.strategy);
  png_write_info(png, info);
  for (int y = 0; y < job.height; ++y)
    png_write_row(png, const_cast<png_bytep>(job.rows + static_cast<size_t>(y) * job.stride));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

/// The image's colours in the order they first appear, and each pixel's index among them;
/// false when it has more than 256.
bool paletteOf(const RgbImage& image, std::vector<uint32_t>& colours, std::vector<uint8_t>& indices) {
  // An open-addressed table of the colours seen: key + 1 (0: empty) and its index.
  constexpr uint32_t kSlots = 1024;  // 256 colours at most: a quarter full
  uint32_t keys[kSlots] = {};
  uint8_t values[kSlots];
  const size_t count = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  indices.resize(count);
  colours.clear();
  const uint8_t* p = image.rgb.data();
  uint32_t last = 0xFFFFFFFF;
  uint8_t lastIndex = 0;
  for (size_t i = 0; i < count; ++i, p += 3) {
    const uint32_t rgb = static_cast<uint32_t>(p[0]) << 16 | static_cast<uint32_t>(p[1]) << 8 | p[2];
    if (rgb != last) {
      uint32_t slot = (rgb * 0x9E3779B1u) >> 22;
      while (keys[slot] != 0 && keys[slot] != rgb + 1) slot = (slot + 1) & (kSlots - 1);
      if (keys[slot] == 0) {
        if (colours.size() == 256) return false;
        keys[slot] = rgb + 1;
        values[slot] = static_cast<uint8_t>(colours.size());
        colours.push_back(rgb);
      }
      last = rgb;
      lastIndex = values[slot];
    }
    indices[i] = lastIndex;
  }
  return true;
}

}  // namespace

std::vector<uint8_t> encodePng(const RgbImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() < static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 3)
    throw std::runtime_error("cannot encode PNG: the image has no pixels");
  PngJob job;
  job.width = image.width;
  job.height = image.height;
  std::vector<uint8_t> out;
  // Screens compress well: a buffer of an eighth of the raw size is rarely outgrown.
  out.reserve(image.rgb.size() / 8 + 4096);
  job.out = &out;
  std::vector<uint32_t> colours;
  std::vector<uint8_t> indices, packed;
  std::vector<png_color> palette;
  if (paletteOf(image, colours, indices)) {
    // A palette image (RobotBASIC's screens have a few colours): one byte a pixel at most, 1, 2
    // or 4 bits where the colours are that few; unfiltered, as the PNG specification advises
    // for palettes.
    const size_t n = colours.size();
    job.bitDepth = n <= 2 ? 1 : n <= 4 ? 2 : n <= 16 ? 4 : 8;
    job.colourType = PNG_COLOR_TYPE_PALETTE;
    for (uint32_t c : colours)
      palette.push_back({static_cast<png_byte>(c >> 16), static_cast<png_byte>(c >> 8), static_cast<png_byte>(c)});
    job.palette = palette.data();
    job.paletteSize = static_cast<int>(palette.size());
    const size_t width = static_cast<size_t>(image.width);
    if (job.bitDepth == 8) {
      job.rows = indices.data();
      job.stride = width;
    } else {
      const int perByte = 8 / job.bitDepth;
      job.stride = (width + static_cast<size_t>(perByte) - 1) / static_cast<size_t>(perByte);
      packed.assign(job.stride * static_cast<size_t>(image.height), 0);
      for (size_t y = 0; y < static_cast<size_t>(image.height); ++y) {
        const uint8_t* from = indices.data() + y * width;
        uint8_t* to = packed.data() + y * job.stride;
        for (size_t x = 0; x < width; ++x)
          to[x / static_cast<size_t>(perByte)] |= static_cast<uint8_t>(
              from[x] << ((perByte - 1 - static_cast<int>(x % static_cast<size_t>(perByte))) * job.bitDepth));
      }
      job.rows = packed.data();
    }
    job.filters = PNG_FILTER_NONE;
    job.level = kPaletteLevel;
  } else {
    // More colours (a photograph-like screen, an anti-aliased drawing): RGB, each row with the
    // "up" filter alone instead of libpng's trial of all five, and a fast deflate.
    job.colourType = PNG_COLOR_TYPE_RGB;
    job.rows = image.rgb.data();
    job.stride = static_cast<size_t>(image.width) * 3;
    job.filters = PNG_FILTER_UP;
    job.level = kRgbLevel;
  }
  if (!runPngJob(job)) {
    if (job.error && std::strcmp(job.error, "out of memory") == 0) throw std::bad_alloc();
    throw std::runtime_error(std::string("cannot encode PNG: ") + (job.error ? job.error : "libpng failed"));
  }
  return out;
}

std::string pngDataHref(const Pixels& pixels) {
  return "data:image/png;base64," + base64Encode(encodePng(screenImage(pixels, 1)));
}

namespace {

/// How long a write to a FIFO or a device may make no progress before rb gives up on it: a
/// reader that stopped reading must not hang rb (rb test writes its reports with the signals
/// that end it held back).
constexpr int kStallMs = 10000;

/// True when a signal that ends rb is waiting (held back while rb test grades): a write gives up
/// so that rb can end by it.
bool endingSignalPending() {
  sigset_t pending;
  if (::sigpending(&pending) != 0) return false;
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT})
    if (::sigismember(&pending, s) == 1) return true;
  return false;
}

/// Writes all of `bytes` to `fd`, waiting (poll) while a non-blocking descriptor is full.
bool writeAll(int fd, const char* p, size_t left, const std::string& path, std::string& error) {
  int waited = 0;
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (waited >= kStallMs || endingSignalPending()) {
        error = "cannot write '" + path + "': " +
                (waited >= kStallMs ? "nothing read from it for " + std::to_string(kStallMs / 1000) + " s"
                                    : std::string("interrupted"));
        return false;
      }
      struct pollfd pfd{fd, POLLOUT, 0};
      ::poll(&pfd, 1, 100);
      waited += 100;
      continue;
    }
    if (n <= 0) {
      error = "cannot write '" + path + "': " + std::strerror(n < 0 ? errno : EIO);
      return false;
    }
    waited = 0;
    p += n;
    left -= static_cast<size_t>(n);
  }
  return true;
}

/// Writes to something that is there and is not a regular file (a FIFO, a device, /dev/stdout,
/// a symbolic link to one) as it is: it is never replaced by a file. Opened without waiting: a
/// FIFO nobody reads is an error at once, not a hang.
bool writeInPlace(const std::string& path, const void* bytes, size_t size, std::string& error) {
  struct stat target;
  bool regular = ::stat(path.c_str(), &target) == 0 && S_ISREG(target.st_mode);
  int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NONBLOCK | (regular ? O_TRUNC : 0));
  if (fd < 0) {
    error = "cannot write '" + path + "': " +
            (errno == ENXIO ? std::string("it is a FIFO nothing reads from") : std::strerror(errno));
    return false;
  }
  bool ok = writeAll(fd, static_cast<const char*>(bytes), size, path, error);
  if (::close(fd) != 0 && ok) {
    error = "cannot write '" + path + "': " + std::strerror(errno);
    return false;
  }
  return ok;
}

/// A new file beside `path` under a name no other file has, opened for writing only.
int createTemporary(const std::string& path, std::string& tmp) {
  static const char digits[] = "0123456789abcdefghijklmnopqrstuvwxyz";
  uint64_t seed = static_cast<uint64_t>(::getpid()) * 0x9E3779B97F4A7C15ull ^
                  static_cast<uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  for (int attempt = 0; attempt < 100; ++attempt) {
    tmp = path + ".tmp-";
    for (int i = 0; i < 6; ++i) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      tmp += digits[(seed >> 33) % 36];
    }
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}
}  // namespace

bool makeFolder(const std::string& path, std::string& error) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) return true;
    error = "cannot make the folder '" + path + "': something else of that name is there";
    return false;
  }
  if (::mkdir(path.c_str(), 0777) == 0) return true;
  error = "cannot make the folder '" + path + "': " +
          (errno == ENOENT ? std::string("the folder it would be in does not exist") : std::strerror(errno));
  return false;
}

bool writeFileBytes(const std::string& path, const void* bytes, size_t size, std::string& error) {
  struct stat st, target;
  if (::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    bool targetIsFile = ::stat(path.c_str(), &target) == 0 ? S_ISREG(target.st_mode) : true;
    if (S_ISDIR(st.st_mode) || (S_ISLNK(st.st_mode) && ::stat(path.c_str(), &target) == 0 && S_ISDIR(target.st_mode))) {
      error = "cannot write '" + path + "': it is a folder";
      return false;
    }
    // A device, a FIFO, or a link to one (/dev/stdout): written to. A link to a file is replaced
    // below, never followed: a link planted in a class folder must not lead rb to overwrite
    // another file.
    if (!S_ISLNK(st.st_mode) || !targetIsFile) return writeInPlace(path, bytes, size, error);
  }
  // A regular file (or none yet) is written beside itself under a temporary name, then renamed
  // over: an interrupted write never leaves a truncated picture. The file gets the usual
  // 0666 & ~umask.
  std::string tmp;
  int fd = createTemporary(path, tmp);
  if (fd < 0) {
    error = "cannot write '" + path + "': " + std::strerror(errno);
    return false;
  }
  bool ok = writeAll(fd, static_cast<const char*>(bytes), size, path, error);
  // Close even after a failed write; a failing close (full disk, NFS) is a failed write too.
  if (::close(fd) != 0 && ok) {
    ok = false;
    error = "cannot write '" + path + "': " + std::strerror(errno);
  }
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) {
    ok = false;
    error = "cannot write '" + path + "': " + std::strerror(errno);
  }
  if (!ok) ::unlink(tmp.c_str());
  return ok;
}

bool writePngFile(const std::string& path, const RgbImage& image, std::string& error) {
  std::vector<uint8_t> bytes;
  try {
    bytes = encodePng(image);
  } catch (const std::exception& e) {
    error = "cannot write '" + path + "': " + e.what();
    return false;
  }
  return writeFileBytes(path, bytes.data(), bytes.size(), error);
}

std::optional<RgbImage> readPngFile(const std::string& path, std::string& error) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    error = "cannot read '" + path + "': " + png.message;
    png_image_free(&png);
    return std::nullopt;
  }
  png.format = PNG_FORMAT_RGB;
  RgbImage image;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgb.assign(PNG_IMAGE_SIZE(png), 0);
  if (!png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr)) {
    error = "cannot read '" + path + "': " + png.message;
    png_image_free(&png);
    return std::nullopt;
  }
  return image;
}

}  // namespace rb::render
