// The few lines a run's summary opens with: what range the backbone covers,
// how much of it is main branch, its energy at a few frequencies, and, where
// one exists, its error against the exact mode (the uniform bar).
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/model/bar_model.h>
#include <nsm/scene/contact_parameters.h>
#include <nsm/scene/continuation_parameters.h>

#include <string>
#include <vector>

namespace nsm
{
  std::vector<std::string> backbone_result(const Backbone &backbone, const BarModel &bar,
                                           const ContactParameters &contact, const ContinuationParameters &continuation);
} // namespace nsm
