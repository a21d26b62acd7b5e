// English: the catalogue's index itself (lang/texts.hpp), as a table like every other language's.
#include "lang/lang.hpp"

namespace noneuclid::lang {

extern const Entry kTexts_en[] = {
#define NONEUCLID_TEXT_ENTRY(name, english) {Text::name, english},
    NONEUCLID_TEXTS(NONEUCLID_TEXT_ENTRY)
#undef NONEUCLID_TEXT_ENTRY
};
extern const int kTextsCount_en = sizeof kTexts_en / sizeof kTexts_en[0];

}  // namespace noneuclid::lang
