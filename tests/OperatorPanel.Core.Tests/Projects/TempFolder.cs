namespace OperatorPanel.Core.Tests.Projects;

/// <summary>A fresh folder under the system temp folder, deleted with everything in it on dispose.</summary>
internal sealed class TempFolder : IDisposable
{
    public TempFolder() => Directory.CreateDirectory(Path);

    public string Path { get; } = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "opanel-tests-" + Guid.NewGuid().ToString("N"));

    public string File(string name) => System.IO.Path.Combine(Path, name);

    /// <summary>
    /// Read-only marks are cleared first (outermost first, as the enumeration lists a folder before its content): tests
    /// make files and folders read-only, and a user who is not root may not delete from a read-only folder, nor anyone
    /// a read-only file on Windows.
    /// </summary>
    public void Dispose()
    {
        foreach (var entry in Directory.EnumerateFileSystemEntries(Path, "*", SearchOption.AllDirectories).Prepend(Path))
        {
            System.IO.File.SetAttributes(entry, System.IO.File.GetAttributes(entry) & ~FileAttributes.ReadOnly);
        }

        Directory.Delete(Path, recursive: true);
    }
}
