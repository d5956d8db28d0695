#pragma once
/// What every panel does with a value the user typed: try it on a copy of the case, let scene::checkCase judge it,
/// and either make it one undoable edit of the document or refuse it with a translated sentence that names the
/// field and its allowed range. The rules live in the case schema (scene::limits, checkCase); this is only how the
/// panels speak of them.

#include "hs/scene/CaseSpec.h"

#include <QString>

#include <functional>
#include <vector>

class QLabel;
class QWidget;

namespace hs::widgets {

class CaseDocument;

/// A translated sentence for one problem checkCase found, by its JSON path: "Age must be between 18 and 80 years."
QString describeIssue(const scene::CaseIssue& issue);

/// The problems of `spec` whose path starts with `pathPrefix` ("/patient", "/pathologies/2").
std::vector<scene::CaseIssue> issuesUnder(const scene::CaseSpec& spec, const QString& pathPrefix);

/// Applies `change` to a copy of the document's case. When that leaves no problem under `pathPrefix`, pushes it as
/// one edit (merging with the previous edit of the same `mergeKey`), clears `message` and returns true. Otherwise the
/// document is left as it was, `message` says why (in red) and `field` is marked invalid until the next good value.
bool tryEdit(CaseDocument& document, const QString& text, const std::function<void(scene::CaseSpec&)>& change,
             const QString& pathPrefix, QLabel* message, QWidget* field = nullptr, int mergeKey = 0);

/// Marks a field as holding a refused value (a red frame) or clears the mark.
void markInvalid(QWidget* field, bool invalid);

/// "18 – 80 years": a range as the panels show it beside a field.
QString rangeText(const scene::Range& range, const QString& unit, int decimals = 0);

} // namespace hs::widgets
