// fmt's compiled part, built into hilrig instead of loaded from libfmt.so.9: the process floor
// of a short `hilrig run` (docs/PERFORMANCE.md, "Fixed cost of a run"). Every FMT_FUNC of
// format-inl.h is defined out of line here (FMT_HEADER_ONLY is not set), and the templates
// format.h declares `extern template` are instantiated here, as fmt's own src/format.cc does;
// a symbol missing from this list fails the link, it cannot go wrong silently.

#include <fmt/format-inl.h>

static_assert(FMT_VERSION / 10000 == 9,
              "deps/fmt_library.cpp instantiates fmt 9's extern templates: check them against "
              "this fmt's src/format.cc, or link fmt::fmt-header-only instead");

FMT_BEGIN_NAMESPACE
namespace detail {

template FMT_API auto dragonbox::to_decimal(float x) noexcept -> dragonbox::decimal_fp<float>;
template FMT_API auto dragonbox::to_decimal(double x) noexcept -> dragonbox::decimal_fp<double>;

#ifndef FMT_STATIC_THOUSANDS_SEPARATOR
template FMT_API locale_ref::locale_ref(const std::locale& loc);
template FMT_API auto locale_ref::get<std::locale>() const -> std::locale;
#endif

template FMT_API auto thousands_sep_impl(locale_ref) -> thousands_sep_result<char>;
template FMT_API auto decimal_point_impl(locale_ref) -> char;
template FMT_API void buffer<char>::append(const char*, const char*);
template FMT_API void vformat_to(buffer<char>&, string_view, basic_format_args<FMT_BUFFER_CONTEXT(char)>,
                                 locale_ref);

template FMT_API auto thousands_sep_impl(locale_ref) -> thousands_sep_result<wchar_t>;
template FMT_API auto decimal_point_impl(locale_ref) -> wchar_t;
template FMT_API void buffer<wchar_t>::append(const wchar_t*, const wchar_t*);

} // namespace detail
FMT_END_NAMESPACE
