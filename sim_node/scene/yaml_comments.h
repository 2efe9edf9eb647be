#pragma once
// The comments of a YAML text taken out before yaml-cpp parses it (docs/benchmarks.md,
// "Start-up"): yaml-cpp 0.7's scanner matches every character against its regular expressions,
// and the comments and the blanks that align them are about a third of the instructions it
// spends on the shipped scene and vehicle files.
//
// StripYamlComments returns the text with the words of every comment removed and nothing else
// changed: a comment's '#' stays (after one space where blanks separated it from what comes
// before), because a comment ends a plain scalar, so that the more indented line below it
// stays an error rather than a continuation; a comment line keeps its indentation and '#';
// the blanks at the end of the other lines go. Every line is kept, and everything before a
// '#' keeps its line and column, so the parse, its node marks and the scene layer's
// `file:line` in error messages are those of the original text. Where the scan below cannot be sure what is a comment, it returns the text
// unchanged (yaml-cpp then reads the original, comments and all):
//   - a comment is '#' at the start of a line or after a space, outside quoted scalars and
//     block scalars (YAML 1.2, 6.6: a comment must be separated from other tokens by white
//     space);
//   - a quoted scalar opens at ' or " at the start of a line or after a space or one of
//     [ { , : (every place yaml-cpp can open one; a superset only keeps more text) and runs
//     to its closing quote (\" escaped in double quotes, '' in single quotes) on that line;
//   - flow collections ([ ], { }) may span lines;
//   - a block scalar opens at | or > at the start of a line or after a space, on a line where
//     a ':', '- ' or '? ' indicator comes before it; its content (not touched) is every
//     following line that is blank or indented more than that line (YAML 1.2, 8.1: the
//     content is indented more than its parent node, which starts on that line);
//   - unchanged: a text with a tab, a carriage return, a NUL or a byte order mark, a block
//     indicator with no indicator before it on its line (a root scalar, or a value on the
//     line below its key: its parent's indentation is not that line's) or inside a flow
//     collection, a quoted scalar that does not close on its line, a ] or } that closes
//     nothing, or block scalar content with a " [ ] { }, a ' where a quoted scalar could
//     open or a | or > where a block scalar could (where the scan's block might not be
//     yaml-cpp's: a block indicator inside a plain scalar over several lines is none). yaml-cpp 0.7 reads some malformed texts of that kind without an error, in
//     ways a line scan cannot follow; there the original is what it reads.

#include <string>

namespace towsim::scene::internal {

std::string StripYamlComments(const std::string& text);

}  // namespace towsim::scene::internal
