#include <nsm/model/contact_law.h>

namespace nsm
{
  ContactLaw::ContactLaw(const Scene::Contact &contact)
    : gap_(contact.gap)
    , alpha_(contact.alpha)
    , sign_(contact.sign == ForceSign::physical ? 1.0 : -1.0)
  {}
} // namespace nsm
