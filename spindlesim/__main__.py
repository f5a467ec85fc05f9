from .cli import console

if __name__ == "__main__":  # not again in a worker process that imports the main module
    console()
