// SPDX-License-Identifier: MIT
// The members of AttributeContainer that do not depend on a value type.
#include <cgogn/core/attributes/attribute_container.h>

namespace cgogn
{

std::shared_ptr<AttributeBase> AttributeContainer::find(const std::string& name) const
{
	auto it = std::find_if(attributes_.begin(), attributes_.end(), [&](const auto& a) { return a->name() == name; });
	return it == attributes_.end() ? nullptr : *it;
}

void AttributeContainer::adopt(const std::shared_ptr<AttributeBase>& a)
{
	a->set_nb_chunks(nb_chunks_);
	a->cell_index_ = cell_index_;
	attributes_.push_back(a);
}

} // namespace cgogn
