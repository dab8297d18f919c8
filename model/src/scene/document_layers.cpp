// Document's layer mutators (document.h): the list of layers and which one is current.
#include <finbook/model/document.h>
#include <finbook/model/skeleton/skeleton_join.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace finbook::model {

void Document::insertLayer(int index, Layer layer)
{
    if (layer.id == kNoId || layerIndex(layer.id) >= 0)
        throw std::invalid_argument("Document::insertLayer: the layer needs a new id");
    const Id current = currentLayerId();
    index = std::clamp(index, 0, layerCount());
    for (Frame &f : layer.cels) {
        linkInserted(f);
        resolveJoins(f);
    }
    m_layers.insert(m_layers.begin() + index, std::move(layer));
    m_current = layerIndex(current);
    emit layersChanged();
}

Layer Document::takeLayer(Id layerId)
{
    const int index = layerIndex(layerId);
    if (index < 0)
        throw std::out_of_range("Document::takeLayer: no such layer");
    if (layerCount() == 1)
        throw std::logic_error("Document::takeLayer: a document keeps at least one layer");
    const bool wasCurrent = index == m_current;
    const Id current = currentLayerId();
    Layer taken = std::move(m_layers[std::size_t(index)]);
    m_layers.erase(m_layers.begin() + index);
    // The layer below (or the new bottom one) takes over from a removed current layer.
    m_current = wasCurrent ? std::max(0, index - 1) : layerIndex(current);
    emit layersChanged();
    if (wasCurrent)
        emit currentLayerChanged();
    return taken;
}

void Document::moveLayer(Id layerId, int toIndex)
{
    const int from = layerIndex(layerId);
    if (from < 0)
        throw std::out_of_range("Document::moveLayer: no such layer");
    toIndex = std::clamp(toIndex, 0, layerCount() - 1);
    if (toIndex == from)
        return;
    const Id current = currentLayerId();
    Layer moving = std::move(m_layers[std::size_t(from)]);
    m_layers.erase(m_layers.begin() + from);
    m_layers.insert(m_layers.begin() + toIndex, std::move(moving));
    m_current = layerIndex(current);
    emit layersChanged();
}

void Document::setLayerProperties(Id layerId, const LayerProperties &properties)
{
    Layer &l = mutableLayer(layerId);
    if (l.properties == properties)
        return;
    l.properties = properties;
    const double opacity = std::isfinite(properties.opacity) ? properties.opacity : 1.0;
    const double depth = std::isfinite(properties.depth) ? properties.depth : 0.0;
    l.properties.opacity = std::clamp(opacity, 0.0, 1.0);
    l.properties.depth = std::clamp(depth, kMinLayerDepth, kMaxLayerDepth);
    emit layersChanged();
}

void Document::setCurrentLayer(Id layerId)
{
    const int index = layerIndex(layerId);
    if (index < 0 || index == m_current)
        return;
    m_current = index;
    emit currentLayerChanged();
}

} // namespace finbook::model
