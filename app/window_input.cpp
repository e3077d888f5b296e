// The window's input: keys (dispatched from the key table, input_table.h), the mouse, the fly camera, and
// the stepping cursor they move.
#include "gui_app.h"
#include "step_cursor.h"

namespace airlight {

int GuiApp::stageShown() const { return stageShownBy(technique(), mState.cursor); }

std::pair<int, int> GuiApp::substepState() const {
    const SubstepAt pos = substepAt(technique(), mState.settings, mState.cursor, mOutput.substepCounts);
    return {pos.at, pos.count};
}

std::string GuiApp::stoppedEarly() const {
    return airlight::stoppedEarly(technique(), mState.settings, mState.cursor, mOutput.substepCounts);
}

void GuiApp::moveCursor(StepCursor c) {
    c = normalisedCursor(technique(), c);
    if (c == mState.cursor) return;
    mState.cursor = c;
    mDirty = true;
}

void GuiApp::stepStage(int delta) {
    moveCursor(stageStepped(technique(), mState.settings, mState.cursor, delta));
    mNotice.clear();
}

void GuiApp::stepSubstep(int delta) { setSubstepAt(substepState().first + delta); }

void GuiApp::setSubstepAt(int k) {
    const SubstepMove move = substepMovedTo(technique(), mState.settings, mState.cursor, mOutput.substepCounts, k);
    mNotice = move.notice;
    if (move.notice.empty()) moveCursor(move.cursor);
}

void GuiApp::drawStepTimeline() {
    mTimeline = timelineSegments(technique(), mState.settings, mTimelineRect.min.x, mTimelineRect.max.x, mOutput.substepCounts);
    drawTimeline(*mBackground, *mDrawList, mTimelineRect, mTimeline, mState.cursor, mScale);
    mCanvas.screen.place("timeline", mTimelineRect);
    mCanvas.hits.push_back({mTimelineRect, [this] {
                         mDragTimeline = true;
                         mNotice.clear();
                         moveCursor(timelineCursorAt(mTimeline, mHover.x));
                     }});
}

glm::vec2 GuiApp::cursorPixels(double x, double y) const {
    int ww = 1, wh = 1;
    glfwGetWindowSize(mWindow.handle(), &ww, &wh);
    const glm::ivec2 fb = mWindow.framebufferSize();
    return {float(x) * float(fb.x) / float(std::max(ww, 1)), float(y) * float(fb.y) / float(std::max(wh, 1))};
}

void GuiApp::onKey(int key, int action, int mods) {
    if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
    const bool repeat = action == GLFW_REPEAT, shift = (mods & GLFW_MOD_SHIFT) != 0;
    mUiInput.shift = shift;
    mUiInput.ctrl = (mods & GLFW_MOD_CONTROL) != 0;
    const KeyState state{mController.mode() == CameraController::Mode::Fly, mLesson != nullptr, mUi->textFocused(),
                         (mods & GLFW_MOD_CONTROL) != 0};
    if (state.text && key == GLFW_KEY_TAB) mTextTab = true;      // completes a path being typed
    if (state.text && (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER)) mTextEnter = true;
    int offset = 0;
    const Command command = commandForKey(key, shift, repeat, state, &offset);
    if (command == Command::LessonKey && mLesson && mLesson->onKey(key, repeat)) return;
    // Widgets take arrows, Enter, Space and the editing keys where the key table binds nothing else (Home,
    // End and Escape reach a widget only while a text field is edited: Escape ends the editing there).
    if (const auto k = uiKey(key); k && (state.text || command == Command::None || command == Command::LessonKey)) {
        mUiInput.keys.push_back(*k);
        return;
    }
    perform(command, offset);
}

void GuiApp::perform(Command command, int offset) {
    switch (command) {
        case Command::None: case Command::FlyMove: case Command::LessonKey: case Command::Pointer: break;
        case Command::Quit: glfwSetWindowShouldClose(mWindow.handle(), GLFW_TRUE); break;
        case Command::NextTechnique: selectTechnique(currentIndex() + 1); break;
        case Command::PrevTechnique: selectTechnique(currentIndex() - 1); break;
        case Command::PickTechnique:
            if (offset < int(mIds.size())) selectTechnique(offset);
            break;
        case Command::NextStage: stepStage(1); break;
        case Command::PrevStage: stepStage(-1); break;
        case Command::NextSubstep: stepSubstep(1); break;
        case Command::PrevSubstep: stepSubstep(-1); break;
        case Command::FirstSubstep: setSubstepAt(1); break;
        case Command::LastSubstep: setSubstepAt(substepState().second); break;
        case Command::NextView: stepView(1); break;
        case Command::PrevView: stepView(-1); break;
        case Command::NextLayer: stepLayer(1); break;
        case Command::PrevLayer: stepLayer(-1); break;
        case Command::FitView: focusedView().transform.fit(); break;
        case Command::SplitBeside: splitFocused(SplitAxis::X); break;
        case Command::SplitBelow: splitFocused(SplitAxis::Y); break;
        case Command::CloseView: closeFocused(); break;
        case Command::Maximise: mGrid.layout.toggleMaximise(mState.focusedView); break;
        case Command::SwapNext: swapFocused(1); break;
        case Command::SwapPrev: swapFocused(-1); break;
        case Command::FocusNext: mState.focusedView = mGrid.layout.next(mState.focusedView, 1); break;
        case Command::FocusPrev: mState.focusedView = mGrid.layout.next(mState.focusedView, -1); break;
        case Command::ToggleDifference: toggleDifference(); break;
        case Command::ToggleGizmo: mShowGizmo = !mShowGizmo; break;
        case Command::InspectPixel: inspectPixelUnderCursor(); break;
        case Command::ToggleComparison: toggleComparison(); break;
        case Command::PlayPause: togglePlaying(); break;
        case Command::ExportView: exportView(); break;
        case Command::ExportWindow: exportWindow(); break;
        case Command::SaveSession: saveSessionNow(); break;
        case Command::LoadSession: loadSessionNow(); break;
        case Command::ToggleCameraMode: mController.toggleMode(); break;
        case Command::ResetCamera:
            mController.reset();
            mDirty = true;
            break;
        case Command::AutoExposure:
            mState.exposureSet = false;  // auto exposure again on the next frame
            if (!mOutput.final.empty()) {
                mState.exposure = std::round(std::log2(autoExposure(mOutput.final)) / kExposureStep) * kExposureStep;
                mState.exposureSet = true;
            }
            break;
        case Command::ExposureUp: mState.exposure += kExposureStep; break;
        case Command::ExposureDown: mState.exposure -= kExposureStep; break;
        case Command::UiScaleUp: setUiScale(mUiScale * 1.25f); break;
        case Command::UiScaleDown: setUiScale(mUiScale / 1.25f); break;
        case Command::ToggleFullscreen: toggleFullscreen(); break;
    }
}

void GuiApp::onChar(unsigned codepoint) {
    if (mUiInput.ctrl) return;  // Ctrl+= is the UI scale, not exposure
    if (!mUi->textFocused()) {
        perform(commandForChar(codepoint), 0);
        return;
    }
    // UTF-8 for the field being edited.
    std::string& t = mUiInput.text;
    if (codepoint < 0x80) {
        t += char(codepoint);
    } else if (codepoint < 0x800) {
        t += char(0xc0 | (codepoint >> 6)), t += char(0x80 | (codepoint & 0x3f));
    } else if (codepoint < 0x10000) {
        t += char(0xe0 | (codepoint >> 12)), t += char(0x80 | ((codepoint >> 6) & 0x3f)), t += char(0x80 | (codepoint & 0x3f));
    } else if (codepoint < 0x110000) {
        t += char(0xf0 | (codepoint >> 18)), t += char(0x80 | ((codepoint >> 12) & 0x3f));
        t += char(0x80 | ((codepoint >> 6) & 0x3f)), t += char(0x80 | (codepoint & 0x3f));
    }
}

// Files dropped on the window: the first scene file (.gltf, .glb) opens.
void GuiApp::onDrop(const std::vector<std::string>& paths) {
    for (const std::string& p : paths)
        if (isSceneFile(p)) {
            openSceneFile(p);
            return;
        }
    if (!paths.empty()) mError = "dropped '" + paths.front() + "': not a .gltf or .glb file";
}

void GuiApp::onMouseButton(int button, int action) {
    double x = 0, y = 0;
    glfwGetCursorPos(mWindow.handle(), &x, &y);
    onMouseButtonAt(button, action, cursorPixels(x, y));
}

void GuiApp::onMouseButtonAt(int button, int action, glm::vec2 p) {
    if (action == GLFW_RELEASE && mDragTimeline) {
        mDragTimeline = false;
        return;
    }
    if (action == GLFW_PRESS) {
        if (button == GLFW_MOUSE_BUTTON_LEFT) {
            for (const auto& [rect, action2] : mCanvas.hits) {
                if (rect.contains(p)) {
                    action2();
                    return;
                }
            }
        }
        if (mParamsRect.contains(p)) return;  // the widgets read the button state themselves
        // A widget (or an open list hanging over a view) was under this very point last frame.
        if (mUi->hot() != 0 && p == mHoverDrawn) return;
        for (const Rect& r : mStripRects)
            if (r.contains(p)) return;
        for (const Rect& r : mDividerRects)  // the splitter widget takes the drag
            if (r.contains(p)) return;
        if (button == GLFW_MOUSE_BUTTON_LEFT) {
            if (auto handle = gizmoHandleAt(p)) {
                mGizmoDrag = handle;
                mState.focusedView = handle->view;
                return;
            }
        }
        const int view = ViewLayout::hit(mCells, p);
        if (view >= 0 && mGrid.views.count(view)) {
            mState.focusedView = view;  // any click in a view focuses it
            const ViewState& v = mGrid.views.at(view);
            if (button == GLFW_MOUSE_BUTTON_LEFT && v.title.contains(p)) {
                mDragTitle = view;  // dropped on another view: the two swap places
                return;
            }
            if (button == GLFW_MOUSE_BUTTON_LEFT && v.image.contains(p) && isOrbitView(v)) {
                mDragOrbit = view;  // an orbit view: dragging turns its camera
                mLastCursor = p;
                return;
            }
            if (v.image.contains(p) && v.transform.zoom > 1.0) {
                mDragView = view;  // zoomed in: dragging pans the view, not the camera
                mLastCursor = p;
                return;
            }
        }
        if (!mViewArea.contains(p)) return;
        mDragButton = button;
        mLastCursor = p;
    } else if (action == GLFW_RELEASE && mDragTitle >= 0) {
        const int target = ViewLayout::hit(mCells, p);
        if (target >= 0 && target != mDragTitle) mGrid.layout.swap(mDragTitle, target);
        mDragTitle = -1;
    } else if (action == GLFW_RELEASE && mGizmoDrag) {
        mGizmoDrag.reset();
        if (mReduced) mDirty = true;  // the full size follows
    } else if (action == GLFW_RELEASE && mDragOrbit >= 0) {
        mDragOrbit = -1;
    } else if (action == GLFW_RELEASE && mDragView >= 0) {
        mDragView = -1;
    } else if (action == GLFW_RELEASE && button == mDragButton) {
        mDragButton = -1;
        if (mReduced) mDirty = true;
    }
}

void GuiApp::onCursor(double x, double y) { onCursorPixels(cursorPixels(x, y)); }

bool GuiApp::isOrbitView(const ViewState& v) const {
    const auto& all = mOutput.intermediates;
    return mHaveOutput && v.index >= 0 && v.index < int(all.size()) && all[std::size_t(v.index)].id == v.content &&
           all[std::size_t(v.index)].orbit && technique().controls().orbitCamera;
}

void GuiApp::turnOrbitView(glm::vec2 d) {
    double yaw = mState.settings.at(viz::kOrbitYaw) - 0.4 * double(d.x);
    yaw = std::remainder(yaw, 360.0);
    mState.settings[viz::kOrbitYaw] = yaw;
    mState.settings[viz::kOrbitPitch] = std::clamp(mState.settings.at(viz::kOrbitPitch) + 0.4 * double(d.y), -89.0, 89.0);
    mDirty = true;
}

void GuiApp::onCursorPixels(glm::vec2 p) {
    mHover = p;
    if (mDragTimeline) {
        moveCursor(timelineCursorAt(mTimeline, p.x));
        return;
    }
    if (mGizmoDrag) {
        dragGizmo(p);
        return;
    }
    if (mDragOrbit >= 0) {
        turnOrbitView(p - mLastCursor);
        mLastCursor = p;
        return;
    }
    if (mDragView >= 0 && mGrid.views.count(mDragView)) {
        ViewState& v = mGrid.views.at(mDragView);
        v.transform.panBy(glm::dvec2((p - mLastCursor) / glm::max(v.image.size(), glm::vec2(1.0f))));
        mLastCursor = p;
        return;
    }
    if (mDragButton < 0) return;
    const glm::dvec2 d = glm::dvec2(p - mLastCursor);
    mLastCursor = p;
    if (d == glm::dvec2(0.0)) return;
    const double paneHeight = std::max(1.0f, mImageHeight);
    const bool orbitMode = mController.mode() == CameraController::Mode::Orbit;
    if (orbitMode && mDragButton == GLFW_MOUSE_BUTTON_LEFT) {
        // Dragging right turns the scene right: the eye moves the other way round the target.
        mController.orbit(-d.x * kOrbitRadiansPerPixel, d.y * kOrbitRadiansPerPixel);
    } else if (orbitMode) {
        // The scene follows the cursor: the camera moves against the drag.
        mController.pan(-d.x / paneHeight, d.y / paneHeight);
    } else if (mDragButton == GLFW_MOUSE_BUTTON_RIGHT || mDragButton == GLFW_MOUSE_BUTTON_LEFT) {
        mController.look(-d.x * kLookRadiansPerPixel, -d.y * kLookRadiansPerPixel);
    } else {
        mController.pan(-d.x / paneHeight, d.y / paneHeight);
    }
    mDirty = true;
}

void GuiApp::onScroll(double dy) {
    if (mLesson && mLesson->area().contains(mHover)) {
        mLesson->scroll(float(dy));
        return;
    }
    bool overWidgets = mParamsRect.contains(mHover);
    for (const Rect& r : mStripRects) overWidgets = overWidgets || r.contains(mHover);
    if (overWidgets) {
        mUiInput.wheel += float(dy);
        return;
    }
    const int view = ViewLayout::hit(mCells, mHover);
    if (view >= 0 && mGrid.views.count(view) && isOrbitView(mGrid.views.at(view)) && mGrid.views.at(view).image.contains(mHover)) {
        // An orbit view: the wheel moves its own camera in (mesh_zoom, 1.25x a notch), not the texture.
        const viz::ParamInfo zoom = viz::orbitParams("")[2];
        mState.settings[viz::kOrbitZoom] =
            std::clamp(mState.settings.at(viz::kOrbitZoom) * std::pow(1.25, dy), zoom.minValue, zoom.maxValue);
        mDirty = true;
        return;
    }
    if (view >= 0 && mGrid.views.count(view) && mGrid.views.at(view).content != "final" && mGrid.views.at(view).image.contains(mHover)) {
        // The wheel over a view zooms it about the cursor (the camera stays); over the final frame
        // it moves the camera.
        ViewState& v = mGrid.views.at(view);
        v.transform.zoomAt(glm::dvec2((mHover - v.image.min) / v.image.size()), std::pow(1.25, dy));
        return;
    }
    // Titles, readouts and histograms do not move the camera.
    if (view >= 0 && mGrid.views.count(view) && !mGrid.views.at(view).image.contains(mHover)) return;
    if (!mViewArea.contains(mHover)) return;
    if (mController.mode() == CameraController::Mode::Orbit) {
        mController.zoom(dy);
    } else {
        mController.move({0.0, 0.0, 0.1 * dy});
    }
    mDirty = true;
}

bool GuiApp::keyDown(int key) const { return glfwGetKey(mWindow.handle(), key) == GLFW_PRESS || key == mScript.heldKey(); }

bool GuiApp::anyFlyKeyDown() const {
    for (int key : {GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E})
        if (keyDown(key)) return true;
    return false;
}

void GuiApp::fly(double dt) {
    const auto down = [&](int key) { return keyDown(key) ? 1.0 : 0.0; };
    const glm::dvec3 dir{down(GLFW_KEY_D) - down(GLFW_KEY_A), down(GLFW_KEY_E) - down(GLFW_KEY_Q),
                         down(GLFW_KEY_W) - down(GLFW_KEY_S)};
    if (dir == glm::dvec3(0.0)) return;
    const bool fast = keyDown(GLFW_KEY_LEFT_SHIFT) || (mScript.heldKey() >= 0 && mScript.heldShift());
    mController.move(dir * (kFlySpeed * dt * (fast ? 4.0 : 1.0)));
    mDirty = true;
}

}  // namespace airlight
