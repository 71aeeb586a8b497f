#include "scene/scene_object.hpp"

#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace fx {

glm::vec3 motionOffset(const Motion& motion, double seconds) {
    if (motion.type == MotionType::none || !(motion.periodSeconds > 0.0f) || !std::isfinite(seconds))
        return glm::vec3(0.0f);
    // Wrap in double first: after hours, seconds / period in float would have lost the fraction.
    double cycles = seconds / double(motion.periodSeconds) + double(motion.phaseDegrees) / 360.0;
    double fraction = cycles - std::floor(cycles);
    float angle = static_cast<float>(fraction * 2.0 * glm::pi<double>());
    if (motion.type == MotionType::circle)
        return {motion.radius * std::cos(angle), 0.0f, motion.radius * std::sin(angle)};
    // bob: from the rest position up to the amplitude and back, never below the rest position.
    return {0.0f, motion.amplitude * 0.5f * (1.0f - std::cos(angle)), 0.0f};
}

glm::mat4 modelMatrix(const Transform& transform) {
    glm::mat4 model = glm::translate(glm::mat4(1.0f), transform.position);
    model = glm::rotate(model, glm::radians(transform.rotationDegrees.z), glm::vec3(0.0f, 0.0f, 1.0f));
    model = glm::rotate(model, glm::radians(transform.rotationDegrees.y), glm::vec3(0.0f, 1.0f, 0.0f));
    model = glm::rotate(model, glm::radians(transform.rotationDegrees.x), glm::vec3(1.0f, 0.0f, 0.0f));
    return glm::scale(model, transform.scale);
}

}  // namespace fx
