// Irradiance caching on the device (DESIGN.md §6.2; `radcache render --method ic`): a G-buffer
// of camera samples, records placed coarse to fine where the cache does not yet cover the
// image, computed by stratified hemisphere sampling with gradients, inserted on the host with
// gradient-limited, neighbor-clamped radii into a world-space grid, and a shading pass that
// interpolates them. Owns its buffers; reports its statistics.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "image/image.h"
#include "methods/caching/glossy_cache.h"
#include "methods/caching/irradiance_records.h"
#include "methods/caching/pipeline_device_split.h"
#include "methods/caching/pipeline_plugins.h"
#include "methods/frame_scene.h"
#include "methods/radiance_source.h"
#include "methods/shared_settings.h"

namespace rc {

// A record spacing: pixels (of the projected pixel footprint) or scene units.
struct Spacing {
    float value = 0.0f;
    bool world = false;
};
// "4", "4px" (pixels) or "0.5u" (scene units); Error (exit status 2) naming `option` otherwise.
Spacing parse_spacing(const std::string& text, const std::string& option);
// The length a spacing bounds a record's radius R to at a sample whose pixel (footprint) has
// that world size: R_min and R_max in multiples of the projected pixel size (course, "Minimum by
// projected pixel size": Tabellion and Lamorlette's 1.5x-3x for R_min, 10x for R_max; Radiance's
// R_max = 64 R_min) or in scene units.
float spacing_bound(const Spacing& spacing, float footprint);

struct PipelineSettings : SharedSettings {
    PipelineSettings() { spp = 4; }
    float accuracy = 0.35f;  // a: records influence points within a R
    int rays = 1024;         // hemisphere rays per record (M x N strata, N ~ pi M)
    int deeper_rays = 0;     // per record of the deeper levels (--ic-deeper-rays; 0: rays / 4)
    Spacing min_spacing{8.0f, false};  // bounds on a record's radius R (course: R_min, R_max)
    Spacing max_spacing{64.0f, false};
    int bounces = 2;        // cache levels: 1 path-traces beyond the hemisphere rays' hits; n > 1
                            // reads level k + 1 there for levels k < n (docs/irradiance-caching.md:
                            // two levels cut the Cornell box's indirect relMSE 3x, two-rooms' 10x)
    int light_samples = 1;  // the render pass's light samples per camera hit (--light-samples)
    // Camera samples first_sample .. first_sample + spp - 1 of each pixel (a later pass of a
    // render by time draws the samples a longer render would give those indices).
    int first_sample = 0;
    std::filesystem::path cache_in;   // records to start from
    std::filesystem::path cache_out;  // where to save the records
    bool records_overlay = true;      // draw the `records` layer
};

// One pass of placement: records created at one cache level (0: the camera's) from candidates
// at one pixel stride (0: hemisphere hits of the level above).
struct PlacementPass {
    int level = 0;
    int stride = 0;
    size_t candidates = 0;
    size_t uncovered = 0;
    size_t records = 0;
};

struct PipelineStats {
    std::vector<PlacementPass> passes;
    std::vector<PipelineDeviceShare> devices;  // with peers: per device, its share of the work
    std::vector<size_t> level_records;  // in each level's cache at the end (loaded ones included)
    size_t records = 0;                 // in the first level at the end
    size_t loaded_records = 0;          // all levels
    int strata_m = 0;
    int strata_n = 0;
    int deeper_strata_m = 0;  // of the deeper levels' records
    int deeper_strata_n = 0;
    uint64_t record_rays = 0;   // rays traced for records (hemisphere rays and their paths)
    uint64_t shading_rays = 0;  // rays traced by the shading pass
    double gbuffer_seconds = 0.0;
    double placement_seconds = 0.0;  // coverage queries and candidate selection, first level
    double record_seconds = 0.0;     // record computation, deeper levels' placement included
    double insertion_seconds = 0.0;  // host insertion and the device records and grid
    // The final splat of every record over every camera sample; with peers, the host's part of
    // it (records, grid and splat tiles), the splat itself being shared with the render pass.
    double splatting_seconds = 0.0;
    // The render pass: direct light, the splat buffer, lobes; with peers, the splat and the
    // render pass of every chunk on every device.
    double shading_seconds = 0.0;
    size_t cache_bytes = 0;  // the first level on the device: records, payloads, splat buffer
    uint64_t nonfinite_samples = 0;
    int64_t first_nonfinite_pixel = -1;
};

// The largest weight a record gets (near its centre, where Ward's weight grows without bound).
constexpr float kRecordMaxWeight = 1.0e4f;

// The layers of an irradiance-cached image, in channel order: beauty (R, G, B), direct, indirect
// (3 channels each), albedo, normal, coverage (1 channel: the smallest sum of record weights over
// the pixel's camera samples the cache serves; 0 when one is uncovered or none is served), records
// (record centres red and influence borders green over the image at half brightness; only when
// PipelineSettings::records_overlay).
extern const char* const kCachePipelineAovs[7];

// Where a record is to be computed.
struct RecordSite {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec3 origin{0.0f};  // the surface point offset for leaving rays
    float r_min = 0.0f;
    float r_max = 0.0f;
    int primitive = -1;  // the triangle the site lies on (-1: unknown)
    // The random stream (within its level) of the record computed here: -1 takes the level's
    // next; a record computed again in its predecessor's place may take the predecessor's, so
    // that the two draw the same directions (temporal caching).
    int64_t stream = -1;
};

// A batch of records as the record kernels computed them, still on the device.
struct RecordBatch {
    const shared::IcParams& params;         // the kernels' parameters; level: the records'
                                            // cache level
    const Buffer<shared::Record>& records;  // count records (position, normal; radius 0)
    const shared::Record* record_values;    // the same on the host
    const Buffer<shared::float4>& origins;  // where their rays leave
    const Buffer<unsigned>& streams;        // their random streams (within the level)
    const unsigned* stream_values;          // the same, count of them
    const Buffer<shared::float4>& cells;    // count x M N cells: (L.rgb, hit distance)
    const RecordSite* sites;                // count sites, in the batch's order
    size_t count;
};

// Sees every batch of records the kernels compute at every cache level, in computation order
// (which is, level by level, the order they are inserted in).
class RecordBatchObserver {
   public:
    virtual ~RecordBatchObserver() = default;
    virtual void observe(const RecordBatch& batch) = 0;
};

// How records sample their hemisphere and how deeper cache levels place their records.
struct RecordSampling {
    int m = 18;         // polar strata
    int n = 57;         // azimuthal strata
    int deeper_m = 18;  // the same at the deeper cache levels (fewer rays: --ic-deeper-rays)
    int deeper_n = 57;
    int max_depth = 64;
    int rr_depth = 3;
    uint64_t seed = 0;
    bool include_emission = false;      // count emitters the hemisphere rays see (tests)
    int levels = 1;                     // cache levels (--ic-bounces)
    float accuracy = 0.35f;             // of every level
    Spacing min_spacing{8.0f, false};   // of the deeper levels, where a "pixel" is the footprint
    Spacing max_spacing{64.0f, false};  // of one hemisphere stratum's cone
    const RadianceSource* source = nullptr;  // read at the last level's hemisphere hits
};

// The programs irradiance caching builds with `options`: its kernels, and the hemisphere
// sampling's for each level's source (the next level's records; at the last level `last_source`,
// RC_RADIANCE_PATH, or RC_RADIANCE_GRID with --ic-ivg).
std::vector<ProgramRequest> cache_pipeline_programs(const PipelineSettings& options,
                                                    int last_source);

// M x N strata with N ~ pi M and M N close to `rays`, at every level.
RecordSampling strata_for(int rays);

struct DeviceRecords;  // record_level_source.h

class CachePipeline : private FrameBound {
   public:
    // With the frame's peers (several devices), the record batches' hemisphere sampling (but
    // where the hemisphere rays read PipelinePlugins::beyond, or an observer sees the
    // batches) and the final pass are shared among the devices (pipeline_device_split.h); placement
    // and insertion stay on the first device and the host. The image is bitwise the one-device
    // image on identical devices. `plugins`: what the pipeline reads beyond its records and who
    // sees its batches, for every frame this pipeline renders.
    explicit CachePipeline(const FrameScene& frame, PipelinePlugins plugins = {});

    // begin(), the placement (from options.cache_in's records when given; saved to
    // options.cache_out), finish().
    Image render(const PipelineSettings& options, PipelineStats* stats = nullptr);

    // A later pass of a render by time (methods/sample_passes.h) after render(): the camera
    // samples of `options` (options.first_sample on), covered by the records so far and new ones
    // where they are not (saved to options.cache_out), then finish(). The statistics are the
    // pass's own; the records counted are all of them.
    Image render_more(const PipelineSettings& options, PipelineStats* stats = nullptr);

    // render() in steps, for callers that keep first-level records across frames (temporal
    // caching). begin(): the G-buffer of the camera samples, empty stores; first-level records
    // take random streams from 0.
    void begin(const PipelineSettings& options);
    // Which records of `store` weigh at least one camera sample of begin()'s G-buffer that the
    // cache serves positively (1) or none (0).
    std::vector<uint8_t> records_used(const RecordStore& store);
    // Cache level `level`'s records become `store` (its accuracy the cache's); the next record
    // computed at that level takes random stream `next_stream` (the following ones the following
    // streams).
    void set_records(int level, RecordStore store, uint32_t next_stream);
    // First-level records computed at `sites` (in order) and inserted.
    void add_records(const std::vector<RecordSite>& sites);
    // Coarse-to-fine placement over the G-buffer from the first level's records so far.
    void place();
    // The splat buffer, the render pass and the image; the statistics since begin().
    Image finish(PipelineSettings options, PipelineStats* stats = nullptr);
    // The statistics since begin(), with the stores' sizes now.
    PipelineStats current_stats() const;
    // The random stream the next record of `level` will take.
    uint32_t next_stream(int level) const { return next_streams_.at(static_cast<size_t>(level)); }
    int levels() const { return static_cast<int>(stores_.size()); }

    // First-level records at arbitrary sites, numbered from `first_index` (their random streams);
    // with sampling.levels > 1 the deeper levels start empty and get the records the hemisphere
    // rays need.
    std::vector<ComputedRecord> compute_records(const std::vector<RecordSite>& sites,
                                                uint32_t first_index,
                                                const RecordSampling& sampling,
                                                uint64_t* rays = nullptr);

    // (sum w E', sum w) of `store`'s records at G-buffer-like query points, gathered through
    // the world-space record grid.
    std::vector<shared::float4> gather(const RecordStore& store,
                                       const std::vector<shared::GBufferSample>& queries);
    // The same sums by radiance cache splatting: `samples` are the camera samples of `camera`'s
    // image, `spp` per pixel (entry pixel * spp + s), as the G-buffer holds them.
    std::vector<shared::float4> splat(const RecordStore& store, const shared::CameraParams& camera,
                                      int spp, const std::vector<shared::GBufferSample>& samples);

    // The camera samples (G-buffer, entry pixel * spp + s) of the last render(), and its camera.
    std::vector<shared::GBufferSample> camera_samples() const { return gbuffer_.download(); }
    const shared::CameraParams& camera() const { return camera_; }
    // The first level's kernel parameters since begin() (image, camera samples, seed, depths).
    shared::IcParams first_level_params() const { return level_params(0); }

    // The records of cache level `level` (0: the one the camera samples read) after render():
    // irradiance payloads (irradiance_records.h).
    const RecordStore& store(int level = 0) const { return stores_.at(level); }

   private:
    // A placement pass's candidates (IcParams::placement_*): with `columns` candidate columns,
    // candidate q is camera sample q % spp of pixel (stride (q / spp % columns),
    // stride (q / spp / columns)); with stride 0, entry q.
    struct Candidates {
        int stride = 0;
        int spp = 1;
        int columns = 1;
    };
    // tile_depths_ of `samples`, camera samples of `camera`'s image (params: width, height,
    // camera_spp).
    void measure_tile_depths(const Buffer<shared::GBufferSample>& samples,
                             const shared::IcParams& params, const shared::CameraParams& camera);
    // The kernels' parameters of `level` with the candidates of a placement pass.
    shared::IcParams candidate_params(int level, Candidates placement) const;
    // (sum w E', sum w) of `store`'s records (`records`: their device copy) at the candidates
    // `params` names (placement_*) of `samples`: splatted onto `camera`'s image (ic_splat) or,
    // without a camera, gathered through the world-space record grid (ic_gather; `records` must
    // hold the grid).
    Buffer<shared::float4> weighted_sums(const RecordStore& store, const DeviceRecords& records,
                                         const Buffer<shared::GBufferSample>& samples,
                                         const shared::IcParams& params, size_t candidates,
                                         const shared::CameraParams* camera);
    // Places records at `level` where candidates of `samples` are not covered. One pass, or
    // passes until all are covered.
    // Removes the hits on PipelinePlugins::uncached_primitives.
    void drop_uncached(std::vector<shared::GBufferSample>* hits) const;
    void cover(int level, const Buffer<shared::GBufferSample>& samples, Candidates placement,
               size_t candidates, bool until_covered);
    // The candidates of `level` among `samples` that no record covers (deeper levels' without
    // the hits that need no record), in candidate order.
    std::vector<shared::GBufferSample> uncovered_samples(
        int level, const Buffer<shared::GBufferSample>& samples, const shared::IcParams& params,
        size_t candidates);
    // A record's smallest radius at a sample of that footprint (--ic-min-spacing, at least
    // smallest_radius_), and the site of a record placed at sample g.
    float min_radius(float footprint) const;
    RecordSite site_of(const shared::GBufferSample& g) const;
    // Records of `level` at `sites`, numbered from the level's current size.
    std::vector<ComputedRecord> compute_level(int level, const std::vector<RecordSite>& sites);
    void reset(const RecordSampling& sampling);
    // The statistics restarted (the sampling's strata kept).
    void restart_stats();
    // The image size, camera samples and camera of `options` (checked; then `checked` runs),
    // and their G-buffer.
    void sample_camera(const PipelineSettings& options,
                       const std::function<void()>& checked = nullptr);
    // Inserts computed first-level records; timed as insertion.
    void insert_level0(const std::vector<ComputedRecord>& computed);
    // The splat buffer and the render pass over the first level; the film's sums.
    // `glossy`: the glossy buffer the pass reads when params.glossy_cache.
    std::vector<shared::float4> shade(const shared::IcParams& params, bool records_overlay,
                                      const Buffer<shared::RcGlossySample>& glossy);
    // The same on every device of split_ (the glossy buffer copied to every device).
    std::vector<shared::float4> shade_split(const shared::IcParams& params, bool records_overlay,
                                            const Buffer<shared::RcGlossySample>& glossy);
    // A batch's records, origins and random streams on the first device.
    struct BatchBuffers {
        BatchBuffers(Context& context, const RecordBatchInput& batch);
        Buffer<shared::Record> records;
        Buffer<shared::float4> origins;
        Buffer<unsigned> streams;
    };
    // A batch's payloads and distances computed on the first device (`buffers`: the batch
    // there; shown to plugins_.observer with its `sites`); `next`: the level below, read at the
    // hits (null: sampling_.source or path-traced continuation).
    RecordBatchOutput compute_batch(const RecordBatchInput& batch, const BatchBuffers& buffers,
                                    const RecordStore* next, const RecordSite* sites);
    shared::IcParams level_params(int level) const;
    // ic_record_cells built for `source` (one program per source kind).
    Kernel& cells_kernel(const RadianceSource& source);

    Kernel gbuffer_kernel_;
    Kernel hits_kernel_;
    Kernel reduce_kernel_;
    Kernel gather_kernel_;
    Kernel splat_kernel_;
    Kernel tile_depths_kernel_;
    Kernel uncovered_kernel_;
    Kernel select_kernel_;
    Kernel shade_kernel_;
    Kernel records_used_kernel_;
    std::map<std::string, Kernel> cells_kernels_;  // source_kernel's
    PathContinuation path_continuation_;
    RecordSampling sampling_;
    float smallest_radius_ = 0.0f;  // the smallest record radius the scene's extent resolves
    int width_ = 0;                 // of the image render() makes
    int height_ = 0;
    int camera_spp_ = 1;
    int first_sample_ = 0;                         // of the camera samples (IcParams::first_sample)
    shared::CameraParams camera_{};                // of the image render() makes (splatting)
    Buffer<shared::GBufferSample> gbuffer_;        // its camera samples
    std::vector<shared::TileDepths> tile_depths_;  // their depths per splat tile
    std::vector<uint32_t> next_streams_;           // per level: random stream of its next record
    PipelinePlugins plugins_;
    std::vector<RecordStore> stores_;
    PipelineStats stats_;
    std::unique_ptr<PipelineDeviceSplit> split_;  // with the frame's peers
};

}  // namespace rc
