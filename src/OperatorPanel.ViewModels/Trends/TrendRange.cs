namespace OperatorPanel.ViewModels.Trends;

/// <summary>The windows the Trends window offers: live (scrolling with time), or looking back over the history.</summary>
public enum TrendRange
{
    Live,
    LastHour,
    Shift,
    Day,
    Custom,
}
