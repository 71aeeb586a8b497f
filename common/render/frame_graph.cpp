#include "render/frame_graph.hpp"

#include <algorithm>
#include <string_view>
#include <unordered_set>

#include "base/log.hpp"

namespace fx {

FrameGraph::FrameGraph(OutputTarget output)
    : outputSize_{std::max(output.size.width, 0), std::max(output.size.height, 0)} {
    GraphTexture presented;
    presented.view = {std::move(output.name),
                      {outputSize_.width, outputSize_.height, output.format, 1},
                      output.native,
                      TextureOrigin::PresentedOutput};
    textures_.push_back(std::move(presented));
}

FrameGraph::~FrameGraph() {
    releaseTextures();
}

TextureHandle FrameGraph::declareTexture(std::string name, const TextureDesc& desc) {
    GraphTexture texture;
    texture.view.name = std::move(name);
    texture.view.origin = TextureOrigin::Transient;
    texture.desc = desc;
    texture.view.spec = resolve(desc, outputSize_);
    textures_.push_back(std::move(texture));
    textureGroups_.resize(textures_.size(), 0);
    textureGroups_.back() = openGroup_ ? openGroup_->id() : 0;
    compiled_ = false;
    return TextureHandle{static_cast<std::uint32_t>(textures_.size() - 1)};
}

TextureHandle FrameGraph::importTexture(std::string name, const TextureSpec& spec, NativeTexture native,
                                        std::optional<TextureSize> sizeRule) {
    GraphTexture texture;
    texture.view = {std::move(name), spec, native, TextureOrigin::Imported};
    texture.importedSize = sizeRule;
    textures_.push_back(std::move(texture));
    textureGroups_.resize(textures_.size(), 0);
    textureGroups_.back() = openGroup_ ? openGroup_->id() : 0;
    compiled_ = false;
    return TextureHandle{static_cast<std::uint32_t>(textures_.size() - 1)};
}

Pass& FrameGraph::addPass(std::string name, Pass::Body body) {
    auto index = static_cast<std::uint32_t>(passes_.size());
    passes_.push_back(std::unique_ptr<Pass>(new Pass(*this, index, std::move(name), std::move(body))));
    if (openGroup_) passes_.back()->joinGroup(*openGroup_);
    compiled_ = false;
    return *passes_.back();
}

void FrameGraph::setUnmet(std::string requirement, std::string reason) {
    for (auto& [name, why] : unmet_) {
        if (name == requirement) {
            why = std::move(reason);
            return;
        }
    }
    unmet_.emplace_back(std::move(requirement), std::move(reason));
}

const std::string* FrameGraph::unmetReason(std::string_view requirement) const {
    for (const auto& [name, why] : unmet_) {
        if (name == requirement) return &why;
    }
    return nullptr;
}

const PassGroup* FrameGraph::openGroup(const PassGroup* group) {
    const PassGroup* outer = openGroup_;
    openGroup_ = group;
    return outer;
}

void FrameGraph::inspect(std::string textureName) {
    inspectNames_.push_back(std::move(textureName));
    compiled_ = false;
}

void FrameGraph::capture(std::string textureName) {
    captureNames_.push_back(std::move(textureName));
    compiled_ = false;
}

void FrameGraph::capture(TextureHandle texture) {
    if (owns(texture)) capture(textures_[texture.index].view.name);
}

const TextureView& FrameGraph::texture(TextureHandle texture) const {
    static const TextureView kNone{};
    return owns(texture) ? textures_[texture.index].view : kNone;
}

std::optional<TextureHandle> FrameGraph::findTexture(std::string_view name) const {
    for (std::size_t i = 0; i < textures_.size(); ++i) {
        if (textures_[i].view.name == name) return TextureHandle{static_cast<std::uint32_t>(i)};
    }
    return std::nullopt;
}

const Pass* FrameGraph::findPass(std::string_view name) const {
    for (const auto& p : passes_) {
        if (p->name() == name) return p.get();
    }
    return nullptr;
}

Size2D FrameGraph::targetSize(const Pass& pass) const {
    auto colour = pass.colorAttachments();
    if (!colour.empty()) return texture(colour.front()).size();
    if (auto depth = pass.depthAttachment()) return texture(*depth).size();
    auto storage = pass.storageWrites();
    if (!storage.empty()) return texture(storage.front()).size();
    return outputSize_;
}

namespace {

// One error per name that an earlier entry already has, in the order the names come. A set of the
// names seen so far: comparing every pair was most of compile's time at 1000 passes.
std::vector<std::string> duplicateNames(const std::vector<std::string_view>& names, const char* what) {
    std::vector<std::string> errors;
    std::unordered_set<std::string_view> seen;
    seen.reserve(names.size());
    for (std::string_view name : names) {
        if (!seen.insert(name).second) errors.push_back(cat("two ", what, " are named '", name, "'"));
    }
    return errors;
}

void append(std::vector<std::string>& to, std::vector<std::string> more) {
    to.insert(to.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
}

}  // namespace

void FrameGraph::resolveTextures() {
    for (auto& t : textures_) {
        if (t.transient()) t.view.spec = resolve(t.desc, outputSize_);
        t.inspected =
            std::find(inspectNames_.begin(), inspectNames_.end(), t.view.name) != inspectNames_.end();
        t.captured =
            std::find(captureNames_.begin(), captureNames_.end(), t.view.name) != captureNames_.end();
    }
}

Status FrameGraph::compile() {
    resolveTextures();
    compiledGraph_ = {};
    std::vector<std::string> errors;

    std::vector<std::string_view> names;
    names.reserve(std::max(textures_.size(), passes_.size()));
    for (const auto& t : textures_) names.push_back(t.view.name);
    append(errors, duplicateNames(names, "textures"));
    names.clear();
    for (const auto& p : passes_) names.push_back(p->name());
    append(errors, duplicateNames(names, "passes"));
    for (const auto& p : passes_) append(errors, p->declarationErrors());
    append(errors, validateTextureSizes(textures_, outputSize_));
    append(errors, validatePassTargets(passes_, textures_, outputSize_));

    compiledGraph_.roles = collectRoles(passes_, textures_.size());
    append(errors, validateWriters(passes_, textures_, compiledGraph_.roles));
    TopologicalOrder order = stableTopologicalOrder(static_cast<std::uint32_t>(passes_.size()),
                                                    orderConstraints(compiledGraph_.roles));
    if (order.ok()) {
        compiledGraph_.derivedOrder = order.order;
    } else {
        errors.push_back(describeCycle(order, passes_, textures_));
    }

    compiled_ = true;
    compileOk_ = errors.empty();
    executed_ = false;
    if (compileOk_) {
        decideWhatRuns(passes_, textures_, compiledGraph_);
        planLifetimes(passes_, textures_, compiledGraph_);
    }
    buildReport();
    report_.errors = std::move(errors);
    if (compileOk_) return Status::success();
    std::string message = "frame graph: ";
    for (std::size_t i = 0; i < report_.errors.size(); ++i) message += (i ? "\n" : "") + report_.errors[i];
    return Error{message};
}

TextureSpec FrameGraph::modelSpec(const GraphTexture& texture) const {
    switch (texture.view.origin) {
        case TextureOrigin::Transient:
            return resolve(texture.desc, kTrafficModelSize);
        case TextureOrigin::PresentedOutput:
            return {kTrafficModelSize.width, kTrafficModelSize.height, texture.view.spec.format, 1};
        case TextureOrigin::Imported:
            break;
    }
    if (!texture.importedSize) return texture.view.spec;
    return resolve({*texture.importedSize, texture.view.spec.format, texture.view.spec.mipLevels},
                   kTrafficModelSize);
}

void FrameGraph::buildReport() {
    report_ = {};
    report_.outputSize = outputSize_;
    for (const auto& p : passes_) report_.declaredOrder.push_back(p->name());
    for (std::uint32_t i : compiledGraph_.derivedOrder) report_.derivedOrder.push_back(passes_[i]->name());

    // Passes that run in execution order, then the others in derived (or, failing that, declared) order.
    std::vector<std::uint32_t> rows = compiledGraph_.executionOrder;
    std::vector<bool> listed(passes_.size(), false);
    for (std::uint32_t p : rows) listed[p] = true;
    const auto& rest = compiledGraph_.derivedOrder;
    for (std::uint32_t i = 0; i < passes_.size(); ++i) {
        std::uint32_t p = rest.size() == passes_.size() ? rest[i] : i;
        if (!listed[p]) rows.push_back(p);
        listed[p] = true;
    }
    reportSlot_.assign(passes_.size(), 0);
    for (std::uint32_t p : rows) {
        const Pass& pass = *passes_[p];
        PassRecord record;
        record.name = pass.name();
        record.declaredIndex = p;
        record.tag = pass.tag();
        record.group = pass.group();
        if (p < compiledGraph_.verdicts.size()) {
            record.status = compiledGraph_.verdicts[p].status;
            record.reason = compiledGraph_.verdicts[p].reason;
        } else {
            record.status = PassStatus::FrameSkipped;
            record.reason = "frame skipped: the frame graph has errors";
        }
        std::vector<ModelledAccess> modelled;
        for (const auto& a : pass.accesses()) {
            const TextureView& view = textures_[a.texture.index].view;
            TextureUseRecord use{view.name, view.spec, a.usage, a.reads && a.writes};
            (a.writes ? record.writes : record.reads).push_back(std::move(use));
            modelled.push_back({modelSpec(textures_[a.texture.index]), a.reads, a.writes});
        }
        record.taps = pass.taps();
        record.traffic = modelTraffic(modelled.data(), modelled.size());
        reportSlot_[p] = report_.passes.size();
        report_.passes.push_back(std::move(record));
    }

    for (std::size_t t = 0; t < textures_.size(); ++t) {
        const GraphTexture& texture = textures_[t];
        TextureRecord record;
        record.name = texture.view.name;
        record.spec = texture.view.spec;
        record.origin = texture.view.origin;
        record.bytes = textureBytes(texture.view.spec);
        record.inspected = texture.inspected;
        record.captured = texture.captured;
        record.group = t < textureGroups_.size() ? textureGroups_[t] : 0;
        std::optional<std::uint32_t> producer;
        if (t < compiledGraph_.producer.size()) producer = compiledGraph_.producer[t];
        if (producer) record.producer = passes_[*producer]->name();
        if (texture.transient()) {
            const auto& roles = compiledGraph_.roles[t];
            bool used = !roles.creators.empty() || !roles.modifiers.empty() || !roles.readers.empty();
            if (!used) {
                record.reason = "no pass uses it";
            } else if (producer && *producer < compiledGraph_.verdicts.size() &&
                       compiledGraph_.verdicts[*producer].status != PassStatus::Runs) {
                record.reason = compiledGraph_.verdicts[*producer].reason;
            }
        }
        report_.textures.push_back(std::move(record));
    }

    auto unknown = [&](const std::vector<std::string>& wanted) {
        for (const auto& name : wanted) {
            bool known = std::any_of(textures_.begin(), textures_.end(),
                                     [&](const GraphTexture& t) { return t.view.name == name; });
            auto& list = report_.unknownTargets;
            if (!known && std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
        }
    };
    unknown(inspectNames_);
    unknown(captureNames_);
}

PassRecord& FrameGraph::recordOf(std::uint32_t pass) {
    return report_.passes[reportSlot_[pass]];
}

Status FrameGraph::executeDeclared(TexturePool& pool, PassExecutor& executor) {
    if (!compiled_) compile();
    if (!compileOk_)
        return Error{cat("frame graph: not executed, it has ", report_.errors.size(), " error(s)")};
    if (executed_) return Error{"frame graph: execute() called twice for one frame"};
    executed_ = true;
    pool_ = &pool;

    if (outputSize_.empty()) {
        for (std::uint32_t p : compiledGraph_.executionOrder) {
            recordOf(p).status = PassStatus::FrameSkipped;
            recordOf(p).reason = cat("frame skipped: the output is ", toString(outputSize_));
        }
        report_.pool = pool.stats();
        return Status::success();
    }

    executor.beginFrame(*this);
    for (std::uint32_t p : compiledGraph_.executionOrder) {
        const Pass& pass = *passes_[p];
        for (std::uint32_t t : compiledGraph_.acquireBefore[p]) {
            GraphTexture& texture = textures_[t];
            texture.view.native = pool.acquire(texture.view.spec, texture.view.name);
            report_.textures[t].allocated = texture.view.native != 0;
            if (texture.view.native == 0) report_.textures[t].reason = "the allocator failed";
            held_.push_back(t);
        }
        PassContext ctx(*this, pass);
        bool runs = executor.beginPass(pass, ctx);
        if (runs && pass.body()) pass.body()(ctx);
        PassRecord& record = recordOf(p);
        record.executed = runs;
        if (!runs) {
            record.status = PassStatus::ExecutorFailed;
            record.reason = "the executor could not start it";  // endPass may say more
        }
        executor.endPass(pass, record);
        for (std::uint32_t t : compiledGraph_.releaseAfter[p]) {
            GraphTexture& texture = textures_[t];
            if (texture.view.native != 0) pool.release(texture.view.native);
            texture.view.native = 0;  // the pool may hand it to the next texture: nobody should use it
            held_.erase(std::remove(held_.begin(), held_.end(), t), held_.end());
        }
    }
    report_.pool = pool.stats();
    executor.endFrame(*this, report_);
    return Status::success();
}

void FrameGraph::releaseTextures() {
    if (pool_ == nullptr) return;
    for (std::uint32_t t : held_) {
        GraphTexture& texture = textures_[t];
        if (texture.view.native != 0) pool_->release(texture.view.native);
        texture.view.native = 0;
    }
    held_.clear();
}

}  // namespace fx
