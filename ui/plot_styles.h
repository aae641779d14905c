// The plots the window and the command line draw, with their titles, units and colours.
#pragma once

#include <QColor>
#include <QString>

namespace pat::ui {

/// Series colour number i (distinct on a projector, colour-blind safe first).
QColor series_colour(int i);

namespace plot_titles {
inline const char* kAngles = "Key and hammer";
inline const char* kAnglesAxis = "angle (deg)";
// below zero the hammer felt is pressed into the string (the string is a rigid plane here); short
// enough that the plots and the regulation dock fit 1280 pixels in larger text
inline const char* kGap = "Hammer–string gap (< 0: felt pressed)";
inline const char* kGapAxis = "gap (mm)";
inline const char* kFinger = "Finger force (the touch)";
inline const char* kFingerAxis = "force (N)";
inline const char* kContacts = "Contact forces";
inline const char* kContactsAxis = "force (N)";
}  // namespace plot_titles

}  // namespace pat::ui
