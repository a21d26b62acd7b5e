// write_pdf (app/platform.hpp): a PDF 1.4 file of one image a page, written by hand (the format
// is a few objects and a table of their byte offsets) with each image's RGB rows compressed by
// zlib (PDF's FlateDecode is zlib's format), through AtomicFile as write_png writes.
#include "app/platform.hpp"

#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace noneuclid::platform {

namespace {

// The file as it is built: its bytes, and each object's offset (object n at offsets[n - 1]).
struct Pdf {
    std::string bytes;
    std::vector<std::size_t> offsets;
    void object(const std::string& body) {
        offsets.push_back(bytes.size());
        bytes += std::to_string(offsets.size()) + " 0 obj\n" + body + "\nendobj\n";
    }
};

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
}

// The page's pixels as RGB rows, compressed; false if zlib failed (out of memory).
bool compressed_rgb(const render::Canvas& c, std::string& out) {
    std::vector<unsigned char> rgb(static_cast<std::size_t>(c.width()) * c.height() * 3);
    std::size_t k = 0;
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x) {
            const render::Rgb p = c.get(x, y);
            rgb[k++] = p.r, rgb[k++] = p.g, rgb[k++] = p.b;
        }
    uLongf size = compressBound(static_cast<uLong>(rgb.size()));
    out.resize(size);
    if (compress2(reinterpret_cast<Bytef*>(out.data()), &size, rgb.data(), static_cast<uLong>(rgb.size()), 9) != Z_OK)
        return false;
    out.resize(size);
    return true;
}

}  // namespace

bool write_pdf(const std::string& path, const std::vector<render::Canvas>& pages, double width_pt, double height_pt,
               std::string& error) {
    // Objects: 1 the catalogue, 2 the page tree, then for page i: 3 + 3i the page, 4 + 3i its
    // content (the image scaled to the page), 5 + 3i the image.
    Pdf pdf;
    pdf.bytes = "%PDF-1.4\n%\xE2\xE3\xCF\xD3\n";  // (a binary file, the comment says to a transfer program)
    pdf.object("<< /Type /Catalog /Pages 2 0 R >>");
    std::string kids;
    for (std::size_t i = 0; i < pages.size(); ++i) kids += std::to_string(3 + 3 * i) + " 0 R ";
    pdf.object("<< /Type /Pages /Count " + std::to_string(pages.size()) + " /Kids [" + kids + "] >>");
    const std::string w = number(width_pt), h = number(height_pt);
    for (std::size_t i = 0; i < pages.size(); ++i) {
        const render::Canvas& c = pages[i];
        const std::string page = std::to_string(3 + 3 * i), content = std::to_string(4 + 3 * i),
                          image = std::to_string(5 + 3 * i);
        pdf.object("<< /Type /Page /Parent 2 0 R /MediaBox [0 0 " + w + " " + h + "] /Contents " + content +
                   " 0 R /Resources << /XObject << /Im0 " + image + " 0 R >> >> >>");
        const std::string draw = "q " + w + " 0 0 " + h + " 0 0 cm /Im0 Do Q";
        pdf.object("<< /Length " + std::to_string(draw.size()) + " >>\nstream\n" + draw + "\nendstream");
        std::string data;
        if (!compressed_rgb(c, data)) {
            error = "cannot write " + path + ": zlib could not compress page " + std::to_string(i + 1) +
                    " (out of memory?); it is left as it was.";
            return false;
        }
        pdf.object("<< /Type /XObject /Subtype /Image /Width " + std::to_string(c.width()) + " /Height " +
                   std::to_string(c.height()) + " /ColorSpace /DeviceRGB /BitsPerComponent 8 /Filter /FlateDecode" +
                   " /Length " + std::to_string(data.size()) + " >>\nstream\n" + data + "\nendstream");
        if (stop_signal() != 0) {
            error = "stopped by signal " + std::to_string(stop_signal()) + " while writing " + path +
                    "; it is left as it was.";
            return false;
        }
    }
    const std::size_t xref = pdf.bytes.size();
    pdf.bytes += "xref\n0 " + std::to_string(pdf.offsets.size() + 1) + "\n0000000000 65535 f \n";
    for (const std::size_t at : pdf.offsets) {
        char entry[24];
        std::snprintf(entry, sizeof entry, "%010zu 00000 n \n", at);
        pdf.bytes += entry;
    }
    pdf.bytes += "trailer\n<< /Size " + std::to_string(pdf.offsets.size() + 1) + " /Root 1 0 R >>\nstartxref\n" +
                 std::to_string(xref) + "\n%%EOF\n";
    AtomicFile out;
    if (!out.open(path, error)) return false;
    if (std::fwrite(pdf.bytes.data(), 1, pdf.bytes.size(), out.file()) != pdf.bytes.size()) {
        error = "cannot write " + path + ": " + std::strerror(errno) + " (check the disk has room); it is left as it was.";
        return false;
    }
    return out.commit(error);
}

}  // namespace noneuclid::platform
