#include "app/compare_command.h"

#include <cstdio>
#include <iostream>
#include <sstream>

#include "app/command_errors.h"
#include "app/output_paths.h"
#include "image/image_io.h"

namespace sdfwb::app {

std::string describeComparison(const image::Comparison& c) {
    std::ostringstream out;
    out.setf(std::ios::fixed);
    out.precision(4);
    out << "size: " << c.width << "x" << c.height << "\n"
        << "max abs error: " << c.maxAbs << "/255 at (" << c.worstX << ", " << c.worstY << ")\n"
        << "mean abs error: " << c.meanAbs << "/255\n"
        << "rmse: " << c.rmse << "/255\n"
        << "psnr: " << c.psnr << " dB\n"
        << "pixels above 1/255: " << c.percentAbove1 << " %\n"
        << "pixels above 2/255: " << c.percentAbove2 << " %\n"
        << "pixels above 8/255: " << c.percentAbove8 << " %\n";
    if (c.linearMaxAbs) {
        out << "linear max abs error: " << *c.linearMaxAbs << "\n";
    }
    if (c.nonFiniteA + c.nonFiniteB > 0) {
        out << "non-finite values: " << c.nonFiniteA << " and " << c.nonFiniteB << "\n";
    }
    return out.str();
}

int runCompare(const CompareArguments& a) {
    return runReportingErrors("compare", [&] {
        if (!a.diff.empty()) {
            image::checkWritableFormat(a.diff);
        }
        checkOutputs({{"the first image", a.first}, {"the second image", a.second}}, {{"--diff", a.diff}});
        image::Image first = image::readImage(a.first), second = image::readImage(a.second);
        bool linear = !image::isDisplayEncoded(a.first) && !image::isDisplayEncoded(a.second);
        image::Comparison c = image::compareImages(first, second, linear);
        if (!a.diff.empty()) {
            image::writeImage(a.diff, image::differenceHeatImage(first, second, a.thresholds.hardFailLevel));
        }
        bool ok = image::passes(c, a.thresholds);
        std::cout << describeComparison(c) << (ok ? "result: pass" : "result: FAIL") << "\n";
        return ok ? 0 : kExitCheckFailed;
    });
}

}  // namespace sdfwb::app
