// Typed errors of the field module: what went wrong, on which field id,
// option, file or expression column, so the interpreter can locate it. The codes have
// no names here: the interpreter maps each to a diagnostic kind (interp/kernel/field_eval.cpp),
// whose kebab name and message shape lang/diag_kinds.def declares.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/vec.h"

namespace sm::field {

enum class OptionType;   // field/options.h

enum class FieldErrc {
  UnknownKind,      // Field[n] = NoSuchKind;
  UnknownOption,    // Field[n].NoSuchOption = ...;
  WrongOptionType,  // a number given to a list option, ...
  DuplicateId,      // Field[n] defined twice
  MissingField,     // a reference to an undefined field id
  Cycle,            // fields referencing each other in a loop
  BadValue,         // out-of-range or non-finite option value
  FileError,        // missing/unreadable/ill-formed data file
  ParseError,       // MathEval expression syntax
};

/// Which value a BadValue error is about (the interpreter words each): an option refused
/// for `reason`; a number that is no field id (`value`); a size the field gave (`value`, at
/// `point`); a Distance sample (its index in `value`) or a ChannelWidth coast sample not
/// finite; a ChannelWidth ElementsAcross below 1; more curve samples in one build than
/// their limit (`value`; `option` NumPointsPerCurve when a Distance field asked them).
enum class BadValueWhat { Option, NotFieldIds, Size, DistanceSample, CoastSample, ElementsAcross, TooManySamples };

class FieldError : public std::runtime_error {
 public:
  FieldError(FieldErrc code, std::string message) : std::runtime_error(message), code_(code) {}

  FieldErrc code() const { return code_; }

  int field_id = -1;          ///< the field being defined/built, -1 if none
  std::string option;         ///< the option involved, if any
  std::string suggestion;     ///< closest known name, for "did you mean"
  std::vector<int> ids;       ///< MissingField: the missing id; Cycle: the loop, in order
  std::string file;           ///< FileError: the path
  std::string name;           ///< UnknownKind: the kind named; UnknownOption, BadValue: the field's kind
  std::string expression;     ///< ParseError: the MathEval expression
  std::string reason;  ///< FileError, ParseError, BadValue Option: what is wrong, after the file, column or option
  int column = -1;            ///< ParseError: 1-based column in the expression
  std::optional<Vec3> point;  ///< BadValue from an evaluation: where the field was evaluated
  /// WrongOptionType: the type the option takes and the type of the value given (`name` is
  /// the field's kind, `option` the option).
  OptionType expected{}, given{};
  BadValueWhat bad = BadValueWhat::Option;   ///< BadValue: which value
  std::optional<double> value;  ///< BadValue: the number that is no id, the size, the sample's index, the limit

 private:
  FieldErrc code_;
};

}  // namespace sm::field
