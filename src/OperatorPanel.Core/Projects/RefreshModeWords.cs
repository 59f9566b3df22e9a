using OperatorPanel.Core.Polling;
namespace OperatorPanel.Core.Projects;

/// <summary>
/// The file's words for <see cref="RefreshMode"/>: "continuous" and "triggered", the paper's names for the two modes
/// (seed 000 §7). "onDemand", the type's own name, is read as well.
/// </summary>
internal static class RefreshModeWords
{
    public const string Continuous = "continuous";
    public const string Triggered = "triggered";

    public static string Of(RefreshMode mode) => mode switch
    {
        RefreshMode.Continuous => Continuous,
        RefreshMode.OnDemand => Triggered,
    };

    public static bool TryParse(string text, out RefreshMode mode)
    {
        if (string.Equals(text.Trim(), Triggered, StringComparison.OrdinalIgnoreCase))
        {
            mode = RefreshMode.OnDemand;
            return true;
        }

        return JsonWords.TryParse(text, out mode);
    }
}
