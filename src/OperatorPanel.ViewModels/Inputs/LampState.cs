namespace OperatorPanel.ViewModels.Inputs;

/// <summary>How a lamp is drawn: lit or dark when good, greyed with its last value when stale, crossed out when bad.</summary>
public enum LampState
{
    Bad,
    Off,
    On,
    StaleOff,
    StaleOn,
}
