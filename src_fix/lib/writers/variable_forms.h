// SPDX-License-Identifier: GPL-2.0-or-later
// The forms of a deck's variables, checked before LIGGGHTS parses them: a word where a number
// belongs (`-var Nb many`) otherwise stops in an `if` or a formula with a stock message that
// names neither the variable nor the form, a value outside a jump's labels (`-var start
// resume`) with "Label wasn't found", and a path with a blank splits a command's arguments.
// The command check_variables (doc/command_check_variables.md) and inputs/cluster/cases.py
// (a case table's cells) check the same forms. Plain C++: no LIGGGHTS types.
#ifndef OHMDEM_VARIABLE_FORMS_H
#define OHMDEM_VARIABLE_FORMS_H

#include <functional>
#include <string>

namespace ohmdem {

// What a v_NAME names: no variable, an equal-style one, another style.
enum class VariableKind { None, Equal, Other };

// "" when VALUE has FORM, else what was expected and what was given, for the message. FORM is
// one or more alternatives joined by '|', each one of
//   number   a finite number as a whole (what LIGGGHTS' formulas read: 12, -1.5e-3, .5)
//   v_equal  v_NAME of an equal-style variable (`kind` says what NAME is)
//   path     a file name: no blank or control character, no quote to start with (a LIGGGHTS
//            command splits its line at blanks, and reads a word that starts with a quote up
//            to the closing one)
//   folder   a path without '*' or '%' either (in a run's file names they stand for the step
//            and the process)
//   word     as a path (for keywords: a blank would add words to the command)
// or a literal word the value may be (new|restart, number|lubricant). Throws
// std::invalid_argument for a FORM that is none of these.
std::string form_mismatch(const std::string &form, const std::string &value,
                          const std::function<VariableKind(const std::string &)> &kind);

// True when FORM is made of known alternatives (the deck's own lists are checked by it).
bool valid_form(const std::string &form);

}  // namespace ohmdem

#endif
