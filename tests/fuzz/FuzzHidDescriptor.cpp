// The HID report descriptor parser (docs/haptics-protocol.md, "The report descriptor"): a device built by others
// declares its reports, and the host reads the declaration before it trusts any report size.
// Properties: every item lies inside the descriptor with 0, 1, 2 or 4 data bytes; the declared sizes never fail
// other than by a named error.

#include "FuzzSupport.h"
#include "hs/haptics/HidProtocol.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hs::haptics::hid;
    const auto items = parseDescriptor(data, size);
    if (!items.ok()) {
        hs::fuzz::check(!items.error().detail.empty(), "an error says why");
        return 0;
    }
    for (const DescriptorItem& item : *items) {
        hs::fuzz::check(item.size == 0 || item.size == 1 || item.size == 2 || item.size == 4,
                        "an item has 0, 1, 2 or 4 data bytes");
        hs::fuzz::check(item.offset + 1 + item.size <= size, "an item lies inside the descriptor");
        hs::fuzz::check(item.type <= 2, "an item is main, global or local");
    }
    const auto sizes = declaredReportSizes(*items);
    if (!sizes.ok())
        hs::fuzz::check(!sizes.error().detail.empty(), "an error says why");
    return 0;
}
