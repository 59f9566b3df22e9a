namespace OperatorPanel.ViewModels.Trends;

/// <summary>Line colours, distinct on a white background and for the common colour-vision deficiencies (Okabe-Ito).</summary>
public static class TrendPalette
{
    private static readonly uint[] Colors = [0xFF0072B2, 0xFFD55E00, 0xFF009E73, 0xFFCC79A7, 0xFFE69F00, 0xFF56B4E9, 0xFF000000, 0xFFF0E442];

    public static uint At(int index) => Colors[index % Colors.Length];

    /// <summary>"#0072B2" for a legend swatch.</summary>
    public static string Hex(uint argb) => $"#{argb & 0xFFFFFF:X6}";
}
